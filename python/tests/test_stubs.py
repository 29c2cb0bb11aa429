# SPDX-License-Identifier: MIT
"""The type stubs name everything the package exports, and every name has a
docstring."""

import ast
import pathlib

import cvms

STUB = pathlib.Path(__file__).resolve().parents[1] / "cvms" / "__init__.pyi"


def test_stub_names_every_export():
    tree = ast.parse(STUB.read_text())
    stubbed = {node.name for node in tree.body if isinstance(node, (ast.FunctionDef, ast.ClassDef))}
    stubbed |= {node.target.id for node in tree.body if isinstance(node, ast.AnnAssign)}
    assert set(cvms.__all__) <= stubbed, set(cvms.__all__) - stubbed


def test_every_name_has_a_docstring():
    for name in cvms.__all__:
        value = getattr(cvms, name)
        if callable(value):
            assert value.__doc__, name
    for cls in (cvms.ConvexSet, cvms.DistanceResult, cvms.PenetrationResult):
        for attribute, value in vars(cls).items():
            if not attribute.startswith("_"):
                assert getattr(value, "__doc__", None), f"{cls.__name__}.{attribute}"
