// SPDX-License-Identifier: MIT
// The extension module cvms._cvms: the library's exact convex sets, sums,
// half-spaces and proximity queries for Python (docs/python.md).
//
// Built on the public headers only. Exact values cross the boundary as
// Python ints (numerator and denominator, of any size, through GMP's digit
// strings) or as text; never through a double, except where the API says
// so (ConvexSet.vertices and distance(), the nearest doubles). Every long
// C++ call runs with the GIL released: the arguments are converted to C++
// values first and the results to Python objects after, with the GIL held.
// GMP's memory functions are never changed (other modules share them).
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <climits>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include <cvms/cvms.hpp>

namespace py = pybind11;

namespace {

using cvms::ConvexSet;
using cvms::Error;
using cvms::ErrorCategory;
using cvms::Rational;
using cvms::Vec3;

PyObject* error_type = nullptr;  // cvms.Error, owned by the module

[[noreturn]] void invalid(const std::string& message) {
  throw Error(ErrorCategory::invalid_argument, message);
}

// --- exact numbers, Python -> C++ -------------------------------------------

const py::object& fraction_class() {
  // Leaked on purpose: a static py::object would be released after the
  // interpreter is gone.
  static auto* cls = new py::object(py::module_::import("fractions").attr("Fraction"));
  return *cls;
}

const py::object& decimal_class() {
  static auto* cls = new py::object(py::module_::import("decimal").attr("Decimal"));
  return *cls;
}

mpz_class integer_from_python(py::handle value) {
  int overflow = 0;
  long long small = PyLong_AsLongLongAndOverflow(value.ptr(), &overflow);
  if (small == -1 && PyErr_Occurred()) throw py::error_already_set();
  if (overflow == 0 && small >= LONG_MIN && small <= LONG_MAX) return mpz_class(static_cast<long>(small));
  // Any size: through the hexadecimal digits ("-0x1f"), which GMP reads
  // with base 0 (the prefix gives the base).
  py::str digits = py::reinterpret_steal<py::str>(PyNumber_ToBase(value.ptr(), 16));
  if (!digits) throw py::error_already_set();
  mpz_class result;
  if (result.set_str(std::string(digits), 0) != 0) invalid("cannot read the integer " + std::string(digits));
  return result;
}

// An exact number: int (or any integer type with __index__), float (its
// exact binary value), fractions.Fraction (or any numbers.Rational),
// decimal.Decimal and str (decimal text, "p/q", "1e-3": exactly), numpy
// scalars of these kinds.
Rational rational_from_python(py::handle value) {
  PyObject* p = value.ptr();
  if (PyLong_Check(p)) return Rational(integer_from_python(value));
  if (PyFloat_Check(p)) return cvms::rational_from_double(PyFloat_AS_DOUBLE(p));
  if (PyUnicode_Check(p)) return cvms::parse_rational(std::string(py::str(value)));
  if (PyIndex_Check(p)) {  // numpy integers, bool-like integer types
    py::object integer = py::reinterpret_steal<py::object>(PyNumber_Index(p));
    if (!integer) throw py::error_already_set();
    return Rational(integer_from_python(integer));
  }
  if (py::isinstance(value, decimal_class())) return cvms::parse_rational(std::string(py::str(value)));
  if (py::hasattr(value, "numerator") && py::hasattr(value, "denominator")) {
    Rational q(integer_from_python(value.attr("numerator")), integer_from_python(value.attr("denominator")));
    if (q.get_den() == 0) invalid("a fraction with denominator 0");
    q.canonicalize();
    return q;
  }
  if (py::hasattr(value, "dtype") && PyNumber_Check(p)) {  // numpy float16/32/64 scalars: exact in a double
    double d = PyFloat_AsDouble(p);
    if (d == -1.0 && PyErr_Occurred()) throw py::error_already_set();
    return cvms::rational_from_double(d);
  }
  throw py::type_error("cvms: expected an exact number (int, float, fractions.Fraction, decimal.Decimal or "
                       "a decimal string), got " + std::string(py::str(py::type::handle_of(value).attr("__name__"))));
}

std::vector<Rational> rationals_from_python(py::handle values, const char* what) {
  py::object list;  // owns the list an array becomes
  if (py::isinstance<py::array>(values)) values = list = values.attr("tolist")();
  if (!py::isinstance<py::sequence>(values) || py::isinstance<py::str>(values))
    throw py::type_error(std::string("cvms: ") + what + " must be a sequence of numbers");
  std::vector<Rational> out;
  for (py::handle item : values) out.push_back(rational_from_python(item));
  return out;
}

Vec3 vec3_from_python(py::handle value, const char* what) {
  std::vector<Rational> xyz = rationals_from_python(value, what);
  if (xyz.size() != 3) invalid(std::string(what) + " must have 3 coordinates, not " + std::to_string(xyz.size()));
  return {std::move(xyz[0]), std::move(xyz[1]), std::move(xyz[2])};
}

// Rows of 3 numbers: an (n, 3) numpy array (float arrays taken exactly,
// integer arrays as integers) or a sequence of triples of exact numbers.
// A float array is also returned as doubles (for the hull's fast path).
struct Rows {
  std::vector<Vec3> exact;
  std::vector<std::array<double, 3>> doubles;  // filled iff the input was a float array
  bool from_doubles = false;
};

Rows rows_from_python(py::handle value, const char* what, bool keep_doubles) {
  Rows rows;
  py::object list;  // owns the list an array becomes
  if (py::isinstance<py::array>(value)) {
    py::array array = py::reinterpret_borrow<py::array>(value);
    if (array.size() == 0 && array.ndim() <= 2) return rows;
    if (array.ndim() != 2 || array.shape(1) != 3)
      invalid(std::string(what) + " must be an (n, 3) array, not one of shape " +
              std::string(py::str(value.attr("shape"))));
    const char kind = array.dtype().kind();
    const auto n = static_cast<std::size_t>(array.shape(0));
    if (kind == 'f' && array.dtype().itemsize() <= 8) {
      auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(value);
      if (!d) throw py::error_already_set();
      auto view = d.unchecked<2>();
      for (std::size_t i = 0; i < n; ++i) {
        std::array<double, 3> p{view(i, 0), view(i, 1), view(i, 2)};
        for (int k = 0; k < 3; ++k)
          if (!std::isfinite(p[k]))
            invalid(std::string(what) + ": row " + std::to_string(i) + " has a NaN or infinite coordinate");
        if (keep_doubles) {
          rows.doubles.push_back(p);
        } else {
          rows.exact.push_back({cvms::rational_from_double(p[0]), cvms::rational_from_double(p[1]),
                                cvms::rational_from_double(p[2])});
        }
      }
      rows.from_doubles = keep_doubles;
      return rows;
    }
    if (kind == 'i' || kind == 'b' || (kind == 'u' && array.dtype().itemsize() < 8)) {
      auto ints = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(value);
      if (!ints) throw py::error_already_set();
      auto view = ints.unchecked<2>();
      for (std::size_t i = 0; i < n; ++i) {
        Vec3 p;
        for (int k = 0; k < 3; ++k) p[k] = Rational(mpz_class(static_cast<long>(view(i, k))));
        rows.exact.push_back(std::move(p));
      }
      return rows;
    }
    value = list = value.attr("tolist")();  // object arrays, uint64, long double: element by element
  }
  if (!py::isinstance<py::sequence>(value) || py::isinstance<py::str>(value))
    throw py::type_error(std::string("cvms: ") + what + " must be an (n, 3) array or a sequence of triples");
  for (py::handle row : value) rows.exact.push_back(vec3_from_python(row, what));
  return rows;
}

// --- exact numbers, C++ -> Python -------------------------------------------

py::object int_to_python(const mpz_class& z) {
  if (z.fits_slong_p()) return py::reinterpret_steal<py::object>(PyLong_FromLong(z.get_si()));
  const std::string digits = z.get_str(16);
  PyObject* result = PyLong_FromString(digits.c_str(), nullptr, 16);
  if (result == nullptr) throw py::error_already_set();
  return py::reinterpret_steal<py::object>(result);
}

py::object fraction_to_python(const Rational& q) {
  return fraction_class()(int_to_python(q.get_num()), int_to_python(q.get_den()));
}

// An integer when the value is one (half-space rows are primitive integers,
// directions too), else a Fraction.
py::object number_to_python(const Rational& q) {
  return q.get_den() == 1 ? int_to_python(q.get_num()) : fraction_to_python(q);
}

py::tuple vec3_to_fractions(const Vec3& v) {
  return py::make_tuple(fraction_to_python(v.x), fraction_to_python(v.y), fraction_to_python(v.z));
}

py::tuple vec3_to_ints(const Vec3& v) {
  return py::make_tuple(number_to_python(v.x), number_to_python(v.y), number_to_python(v.z));
}

// --- sets --------------------------------------------------------------------

const ConvexSet& as_set(py::handle value, const char* what) {
  try {
    return py::cast<const ConvexSet&>(value);
  } catch (const py::cast_error&) {
    throw py::type_error(std::string("cvms: ") + what + " must be a cvms.ConvexSet, got " +
                         std::string(py::str(py::type::handle_of(value).attr("__name__"))));
  }
}

cvms::PolygonSoup soup_of(const ConvexSet& s) {
  return s.to_soup();
}

std::string to_off_text(const ConvexSet& s) {
  std::ostringstream out;
  cvms::write(out, s, cvms::FileFormat::off, "<set>");
  return std::move(out).str();
}

ConvexSet from_off_text(const std::string& text) {
  std::istringstream in(text);
  return cvms::convex_set_from_soup(cvms::read_off(in, "<text>"));
}

// The exact volume by the divergence theorem: the sum over the facets'
// fan triangles (v0, vi, vi+1), counter-clockwise from outside, of
// det(v0, vi, vi+1) / 6. The library has no volume function; its facets
// and vertices are all this needs.
Rational volume_of(const ConvexSet& s) {
  Rational six_volume = 0;
  if (s.dimension() < 3) return six_volume;
  cvms::PolygonSoup soup = s.to_soup();
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    auto face = soup.face(f);
    const Vec3& v0 = soup.points[face[0]];
    for (std::size_t i = 1; i + 1 < face.size(); ++i)
      six_volume += cvms::dot(v0, cvms::cross(soup.points[face[i]], soup.points[face[i + 1]]));
  }
  return six_volume / 6;
}

bool contains_point(const ConvexSet& s, const Vec3& p) {
  cvms::HalfspaceSystem system = cvms::to_halfspaces(s);
  for (const auto& row : system.equalities)
    if (cvms::dot(row.normal, p) != row.offset) return false;
  for (const auto& row : system.inequalities)
    if (cvms::dot(row.normal, p) > row.offset) return false;
  return true;
}

py::tuple rows_to_python(const std::vector<cvms::HalfspaceRow>& rows) {
  py::list a, b;
  for (const auto& row : rows) {
    a.append(py::list(vec3_to_ints(row.normal)));
    b.append(number_to_python(row.offset));
  }
  return py::make_tuple(a, b);
}

std::vector<cvms::HalfspaceRow> rows_from_python_ab(py::handle a, py::handle b, const char* name) {
  Rows normals = rows_from_python(a, name, false);
  std::vector<Rational> offsets = rationals_from_python(b, name);
  if (normals.exact.size() != offsets.size())
    invalid(std::string(name) + ": " + std::to_string(normals.exact.size()) + " rows but " +
            std::to_string(offsets.size()) + " right-hand sides");
  std::vector<cvms::HalfspaceRow> rows;
  rows.reserve(offsets.size());
  for (std::size_t i = 0; i < offsets.size(); ++i) rows.push_back({std::move(normals.exact[i]), std::move(offsets[i])});
  return rows;
}

cvms::Options sum_options(unsigned threads, const std::string& algorithm) {
  cvms::Options options;
  options.threads = threads == 0 ? 1 : threads;
  if (algorithm == "cvms") {
    options.algorithm = cvms::Algorithm::cvms;
  } else if (algorithm == "essdms") {
    options.algorithm = cvms::Algorithm::essdms;
  } else if (algorithm == "chms") {
    options.algorithm = cvms::Algorithm::chms;
  } else {
    invalid("unknown algorithm \"" + algorithm + "\" (cvms, essdms or chms)");
  }
  return options;
}

bool same_set(const ConvexSet& a, const ConvexSet& b) {
  if (a.dimension() != b.dimension() || a.num_vertices() != b.num_vertices()) return false;
  std::vector<Vec3> va = a.vertices(), vb = b.vertices();
  std::sort(va.begin(), va.end());
  std::sort(vb.begin(), vb.end());
  return va == vb;  // a polytope is the hull of its vertices
}

std::string repr(const ConvexSet& s) {
  static const char* names[] = {"empty", "point", "segment", "polygon", "polyhedron"};
  std::string text = "<cvms.ConvexSet " + std::string(names[s.dimension() + 1]);
  if (s.dimension() >= 1) text += ", " + std::to_string(s.num_vertices()) + " vertices";
  if (s.dimension() == 3) text += ", " + std::to_string(s.polyhedron().num_facets()) + " facets";
  return text + ">";
}

// The float modes by their Python names.
cvms::FloatMode float_mode_of(const std::string& mode) {
  if (mode == "nearest") return cvms::FloatMode::nearest;
  if (mode == "outer") return cvms::FloatMode::outer;
  throw py::value_error("float mode must be 'nearest' or 'outer', not '" + mode + "'");
}

// write()'s float argument: False (exact), True or "nearest", or "outer".
cvms::Coordinates coordinates_of(const py::object& as_float) {
  if (py::isinstance<py::bool_>(as_float))
    return as_float.cast<bool>() ? cvms::Coordinates::double_ : cvms::Coordinates::exact;
  if (!py::isinstance<py::str>(as_float)) throw py::type_error("float must be a bool, 'nearest' or 'outer'");
  return float_mode_of(as_float.cast<std::string>()) == cvms::FloatMode::outer ? cvms::Coordinates::double_outer
                                                                                : cvms::Coordinates::double_;
}

}  // namespace

PYBIND11_MODULE(_cvms, m) {
  m.doc() = "Exact Minkowski sums, hulls, half-spaces and proximity of convex sets (GMP rationals).";
  m.attr("__version__") = CVMS_VERSION_STRING;

  error_type = PyErr_NewExceptionWithDoc(
      "cvms.Error",
      "Every failure of the library: a ValueError with .category (\"parse\", \"topology\", "
      "\"not_convex\", \"degenerate\", \"limit\", \"io\" or \"invalid_argument\") and .message "
      "(the library's message without the category); str(e) is \"<category>: <message>\".",
      PyExc_ValueError, nullptr);
  if (error_type == nullptr) throw py::error_already_set();
  m.attr("Error") = py::handle(error_type);  // the module keeps the reference
  py::register_exception_translator([](std::exception_ptr thrown) {
    try {
      if (thrown) std::rethrow_exception(thrown);
    } catch (const Error& e) {
      py::object exception = py::reinterpret_borrow<py::object>(error_type)(py::str(e.what()));
      exception.attr("category") = py::str(cvms::to_string(e.category()));
      exception.attr("message") = py::str(e.message());
      PyErr_SetObject(error_type, exception.ptr());
    }
  });

  py::class_<ConvexSet> set(m, "ConvexSet", R"doc(
An exact convex polytope in 3-D of any dimension: empty (-1), a point (0), a
segment (1), a convex polygon in its plane (2) or a polyhedron (3).
Immutable; make one with hull(), from_halfspaces(), read(), zonotope() or the
sums. Picklable (through its exact OFF text). a + b is the Minkowski sum,
-a the reflection, a == b exact equality of the sets.)doc");
  set.def(py::init<>(), "The empty set.");
  set.def_property_readonly("dimension", &ConvexSet::dimension,
                            "-1 for the empty set, 0 point, 1 segment, 2 polygon, 3 polyhedron.");
  set.def_property_readonly("is_empty", &ConvexSet::empty, "True iff this is the empty set.");
  set.def_property_readonly("num_vertices", &ConvexSet::num_vertices, "The number of vertices.");
  set.def_property_readonly(
      "vertices",
      [](const ConvexSet& s) {
        py::array_t<double> out({static_cast<py::ssize_t>(s.num_vertices()), py::ssize_t{3}});
        auto view = out.mutable_unchecked<2>();
        auto put = [&view](py::ssize_t i, const Vec3& p) {
          view(i, 0) = cvms::to_double_nearest(p.x);
          view(i, 1) = cvms::to_double_nearest(p.y);
          view(i, 2) = cvms::to_double_nearest(p.z);
        };
        if (s.dimension() == 3) {
          const cvms::ConvexPolyhedron& p = s.polyhedron();
          py::ssize_t i = 0;
          for (cvms::VertexId v : p.mesh().vertices()) put(i++, p.vertex(v));
        } else {
          std::vector<Vec3> vertices = s.vertices();
          for (std::size_t i = 0; i < vertices.size(); ++i) put(static_cast<py::ssize_t>(i), vertices[i]);
        }
        return out;
      },
      "The vertices as an (n, 3) float64 array, each coordinate the nearest double (ties to even). "
      "Same order as exact_vertices() and the indices of faces and triangles().");
  set.def(
      "exact_vertices",
      [](const ConvexSet& s) {
        py::list out;
        for (const Vec3& v : s.vertices()) out.append(vec3_to_fractions(v));
        return out;
      },
      "The exact vertices: a list of (x, y, z) triples of fractions.Fraction.");
  set.def_property_readonly(
      "faces",
      [](const ConvexSet& s) {
        cvms::PolygonSoup soup = soup_of(s);
        py::list out;
        for (std::size_t f = 0; f < soup.num_faces(); ++f) {
          py::list face;
          for (std::uint32_t i : soup.face(f)) face.append(i);
          out.append(face);
        }
        return out;
      },
      "The faces as lists of vertex indices: a polyhedron's facets, counter-clockwise seen from "
      "outside; a polygon's one face, counter-clockwise seen from its normal; [] below dimension 2.");
  set.def(
      "triangles",
      [](const ConvexSet& s) {
        cvms::PolygonSoup soup = soup_of(s);
        std::size_t count = 0;
        for (std::size_t f = 0; f < soup.num_faces(); ++f) count += soup.face(f).size() - 2;
        py::array_t<std::int64_t> out({static_cast<py::ssize_t>(count), py::ssize_t{3}});
        auto view = out.mutable_unchecked<2>();
        py::ssize_t row = 0;
        for (std::size_t f = 0; f < soup.num_faces(); ++f) {
          auto face = soup.face(f);
          for (std::size_t i = 1; i + 1 < face.size(); ++i, ++row) {
            view(row, 0) = face[0];
            view(row, 1) = face[i];
            view(row, 2) = face[i + 1];
          }
        }
        return out;
      },
      "The faces fan-triangulated: an (m, 3) int64 array of vertex indices, same orientation as faces.");
  set.def(
      "volume",
      [](const ConvexSet& s) {
        Rational v;
        {
          py::gil_scoped_release release;
          v = volume_of(s);
        }
        return fraction_to_python(v);
      },
      "The exact volume as a fractions.Fraction (0 below dimension 3).");
  set.def(
      "contains",
      [](const ConvexSet& s, py::handle point) {
        Vec3 p = vec3_from_python(point, "point");
        py::gil_scoped_release release;
        return contains_point(s, p);
      },
      py::arg("point"), "True iff the point (three exact numbers) lies in the set; the boundary counts.");
  set.def(
      "translated",
      [](const ConvexSet& s, py::handle offset) {
        Vec3 t = vec3_from_python(offset, "offset");
        py::gil_scoped_release release;
        return s.translated(t);
      },
      py::arg("offset"), "The set moved by the vector offset (three exact numbers).");
  set.def(
      "reflected",
      [](const ConvexSet& s) {
        py::gil_scoped_release release;
        return s.reflected();
      },
      "-S = {-x : x in S} (the same as -s).");
  set.def(
      "__neg__",
      [](const ConvexSet& s) {
        py::gil_scoped_release release;
        return s.reflected();
      },
      "-S = {-x : x in S}.");
  set.def(
      "__add__",
      [](const ConvexSet& a, const ConvexSet& b) {
        py::gil_scoped_release release;
        return cvms::minkowski_sum(a, b);
      },
      py::is_operator(), "The Minkowski sum a + b.");
  set.def(
      "halfspaces",
      [](const ConvexSet& s) {
        cvms::HalfspaceSystem system;
        {
          py::gil_scoped_release release;
          system = cvms::to_halfspaces(s);
        }
        return rows_to_python(system.inequalities);
      },
      "The minimal inequalities (A, b), A x <= b, every row primitive integer: lists of ints "
      "(A a list of [a_x, a_y, a_z]). Together with equalities() they describe the set exactly.");
  set.def(
      "equalities",
      [](const ConvexSet& s) {
        cvms::HalfspaceSystem system;
        {
          py::gil_scoped_release release;
          system = cvms::to_halfspaces(s);
        }
        return rows_to_python(system.equalities);
      },
      "The equalities (E, f), E x = f, of a flat set's affine hull (empty lists for a solid): "
      "one for a polygon, two for a segment, three for a point.");
  set.def(
      "to_off",
      [](const ConvexSet& s) {
        py::gil_scoped_release release;
        return to_off_text(s);
      },
      "The set as exact OFF text (what write() puts in a .off file).");
  set.def("__eq__", [](const ConvexSet& a, const ConvexSet& b) { return same_set(a, b); }, py::is_operator(),
          "Exact equality of the sets.");
  set.def("__ne__", [](const ConvexSet& a, const ConvexSet& b) { return !same_set(a, b); }, py::is_operator(),
          "Exact inequality of the sets.");
  set.def("__repr__", &repr);
  // Pickled as a call of cvms.from_off (a Python function, so it pickles by
  // name under every protocol) on the exact OFF text.
  set.def(
      "__reduce__",
      [](const ConvexSet& s) {
        std::string text;
        {
          py::gil_scoped_release release;
          text = to_off_text(s);
        }
        return py::make_tuple(py::module_::import("cvms").attr("from_off"), py::make_tuple(text));
      },
      "Pickling: cvms.from_off of the exact OFF text.");

  m.def(
      "from_off",
      [](const std::string& text) {
        py::gil_scoped_release release;
        return from_off_text(text);
      },
      py::arg("text"), "The convex set an OFF text describes (as read() reads a .off file).");

  m.def(
      "read",
      [](const std::string& path) {
        py::gil_scoped_release release;
        return cvms::read_convex_set(path);
      },
      py::arg("path"),
      "Reads a convex set of any dimension from a file: .off, .obj, .stl or .ply as a mesh (a closed convex "
      "surface, a convex polygon, or points whose hull is taken); any other extension as a list of "
      "'x y z' points. Numbers are read exactly.");
  m.def(
      "write",
      [](const ConvexSet& s, const std::string& path, const py::object& as_float) {
        const cvms::Coordinates coordinates = coordinates_of(as_float);
        py::gil_scoped_release release;
        cvms::write_file(path, s, coordinates);
      },
      py::arg("set"), py::arg("path"), py::arg("float") = false,
      "Writes the set to a file in the format of its extension (.off, .obj, .stl, .ply), exactly unless "
      "float is True or 'nearest' (the exact hull of the vertices' nearest doubles: a valid convex "
      "set in doubles) or 'outer' (a double polyhedron that contains the set), each coordinate as "
      "the shortest decimal of its double. Atomic.");
  m.def(
      "to_float_mesh",
      [](const ConvexSet& s, const std::string& mode) {
        const cvms::FloatMode float_mode = float_mode_of(mode);
        cvms::FloatMesh mesh;
        {
          py::gil_scoped_release release;
          mesh = cvms::to_float_mesh(s, float_mode);
        }
        py::array_t<double> positions({static_cast<py::ssize_t>(mesh.num_vertices()), py::ssize_t{3}});
        std::copy(mesh.positions.begin(), mesh.positions.end(), positions.mutable_data());
        py::array_t<std::uint32_t> triangles({static_cast<py::ssize_t>(mesh.num_triangles()), py::ssize_t{3}});
        std::copy(mesh.triangles.begin(), mesh.triangles.end(), triangles.mutable_data());
        return py::make_tuple(positions, triangles);
      },
      py::arg("set"), py::arg("mode") = "nearest",
      "The set in doubles for engines: (positions, triangles), an (n, 3) float64 array and an (m, 3) "
      "uint32 array of its faces fanned, counter-clockwise from outside. mode 'nearest': the exact "
      "hull of the vertices' nearest doubles, a valid convex set; 'outer': a double polyhedron that "
      "contains the set. The same vertices and faces, in the same order, as write(set, path, mode).");

  m.def(
      "hull",
      [](py::handle points) {
        Rows rows = rows_from_python(points, "points", true);
        py::gil_scoped_release release;
        if (rows.from_doubles) return cvms::convex_hull_set(std::span<const std::array<double, 3>>(rows.doubles));
        return cvms::convex_hull_set(std::span<const Vec3>(rows.exact));
      },
      py::arg("points"),
      "The exact convex hull of points, in the dimension they span. points: an (n, 3) numpy array "
      "(float: each double exactly; int) or a sequence of triples of int, Fraction, Decimal or decimal "
      "strings ('0.1' is exactly 1/10).");
  m.def(
      "from_halfspaces",
      [](py::handle a, py::handle b, py::handle e, py::handle f) {
        cvms::HalfspaceSystem system;
        system.inequalities = rows_from_python_ab(a, b, "A, b");
        if (!e.is_none() || !f.is_none()) {
          if (e.is_none() || f.is_none()) invalid("E and f go together");
          system.equalities = rows_from_python_ab(e, f, "E, f");
        }
        py::gil_scoped_release release;
        return cvms::from_halfspaces(system);
      },
      py::arg("A"), py::arg("b"), py::arg("E") = py::none(), py::arg("f") = py::none(),
      "The exact intersection of the rows A x <= b (and E x = f): A an (m, 3) array or rows of exact "
      "numbers, b m numbers. Redundant rows are harmless; the result may be flat or empty. Raises "
      "cvms.Error (invalid_argument) naming a direction if it is unbounded.");

  m.def(
      "minkowski_sum",
      [](py::handle a, py::handle b, unsigned threads, const std::string& algorithm) {
        cvms::Options options = sum_options(threads, algorithm);
        if (b.is_none()) {
          if (py::isinstance<ConvexSet>(a)) return as_set(a, "a");
          std::vector<ConvexSet> operands;
          for (py::handle item : a) operands.push_back(as_set(item, "every operand"));
          py::gil_scoped_release release;
          return cvms::minkowski_sum(std::span<const ConvexSet>(operands), options);
        }
        const ConvexSet& left = as_set(a, "a");
        const ConvexSet& right = as_set(b, "b");
        py::gil_scoped_release release;
        return cvms::minkowski_sum(left, right, options);
      },
      py::arg("a"), py::arg("b") = py::none(), py::kw_only(), py::arg("threads") = 1,
      py::arg("algorithm") = "cvms",
      "The exact Minkowski sum a + b, or of every set in a sequence (minkowski_sum([a, b, c])). "
      "threads > 1 lets a sum of two polyhedra use worker threads; algorithm is 'cvms' (default), "
      "'essdms' or 'chms' (the hull of all pairwise vertex sums), all with the same result.");
  m.def(
      "minkowski_difference",
      [](const ConvexSet& a, const ConvexSet& b) {
        py::gil_scoped_release release;
        return cvms::minkowski_difference(a, b);
      },
      py::arg("a"), py::arg("b"),
      "a + (-b), the set of differences (the configuration-space obstacle of a translating robot b "
      "among an obstacle a). Not the erosion: see pontryagin_difference.");
  m.def(
      "pontryagin_difference",
      [](const ConvexSet& a, const ConvexSet& b) {
        py::gil_scoped_release release;
        return cvms::pontryagin_difference(a, b);
      },
      py::arg("a"), py::arg("b"),
      "The erosion {x : x + b in a}, exact; may be empty. Raises cvms.Error if b is empty.");
  m.def(
      "zonotope",
      [](py::handle center, py::handle generators) {
        Vec3 c = vec3_from_python(center, "center");
        Rows g = rows_from_python(generators, "generators", false);
        py::gil_scoped_release release;
        return cvms::zonotope(c, std::span<const Vec3>(g.exact));
      },
      py::arg("center"), py::arg("generators"),
      "center + the sum of the segments [-g, g] over the generators g (an (n, 3) array or triples).");

  m.def(
      "intersects",
      [](const ConvexSet& a, const ConvexSet& b) {
        py::gil_scoped_release release;
        return cvms::intersects(a, b);
      },
      py::arg("a"), py::arg("b"), "True iff a and b have a common point (touching counts).");

  py::class_<cvms::DistanceResult>(m, "DistanceResult", "The exact distance of two sets and where it is reached.")
      .def_property_readonly("squared_distance",
                             [](const cvms::DistanceResult& r) { return fraction_to_python(r.squared_distance); },
                             "min |a - b|^2 over a in A, b in B (a Fraction); 0 iff they intersect.")
      .def_property_readonly("witness_a", [](const cvms::DistanceResult& r) { return vec3_to_fractions(r.witness_a); },
                             "A point of A closest to B (a triple of Fractions).")
      .def_property_readonly("witness_b", [](const cvms::DistanceResult& r) { return vec3_to_fractions(r.witness_b); },
                             "A point of B closest to A; |witness_a - witness_b|^2 == squared_distance.")
      .def_readonly("intersect", &cvms::DistanceResult::intersect, "True iff they intersect.")
      .def_property_readonly("distance",
                             [](const cvms::DistanceResult& r) { return cvms::nearest_double_sqrt(r.squared_distance); },
                             "The correctly rounded distance (the double nearest to its exact square root).")
      .def("__repr__", [](const cvms::DistanceResult& r) {
        return "<cvms.DistanceResult squared_distance=" + cvms::to_string(r.squared_distance) +
               (r.intersect ? " intersect" : "") + ">";
      });
  m.def(
      "squared_distance",
      [](const ConvexSet& a, const ConvexSet& b) {
        py::gil_scoped_release release;
        return cvms::squared_distance(a, b);
      },
      py::arg("a"), py::arg("b"), "The exact squared distance of a and b with witness points (a DistanceResult).");
  m.def(
      "distance",
      [](const ConvexSet& a, const ConvexSet& b) {
        py::gil_scoped_release release;
        return cvms::nearest_double_sqrt(cvms::squared_distance(a, b).squared_distance);
      },
      py::arg("a"), py::arg("b"), "The distance of a and b as the correctly rounded float (0.0 if they intersect).");

  py::class_<cvms::PenetrationResult>(m, "PenetrationResult", "How far b must move to separate from a.")
      .def_readonly("intersect", &cvms::PenetrationResult::intersect, "True iff they intersect (touching counts).")
      .def_property_readonly("squared_depth",
                             [](const cvms::PenetrationResult& r) { return fraction_to_python(r.squared_depth); },
                             "The squared minimum translation distance (a Fraction); 0 when apart or touching.")
      .def_property_readonly("direction", [](const cvms::PenetrationResult& r) { return vec3_to_ints(r.direction); },
                             "The primitive integer outward normal (three ints) of the facet of a + (-b) nearest "
                             "the origin: moving b by translation separates them; (0, 0, 0) when apart.")
      .def_property_readonly("offset", [](const cvms::PenetrationResult& r) { return fraction_to_python(r.offset); },
                             "That facet's plane offset: dot(direction, x) = offset on it.")
      .def_property_readonly("translation",
                             [](const cvms::PenetrationResult& r) { return vec3_to_fractions(r.translation()); },
                             "The minimum translation of b, exact (a triple of Fractions).")
      .def_property_readonly("witness_a", [](const cvms::PenetrationResult& r) { return vec3_to_fractions(r.witness_a); },
                             "A point of a: witness_a - witness_b == translation when they intersect; the closest "
                             "points when apart.")
      .def_property_readonly("witness_b", [](const cvms::PenetrationResult& r) { return vec3_to_fractions(r.witness_b); },
                             "A point of b (see witness_a).")
      .def_property_readonly("depth",
                             [](const cvms::PenetrationResult& r) { return cvms::nearest_double_sqrt(r.squared_depth); },
                             "The correctly rounded depth.")
      .def("__repr__", [](const cvms::PenetrationResult& r) {
        return "<cvms.PenetrationResult squared_depth=" + cvms::to_string(r.squared_depth) +
               (r.intersect ? " intersect" : "") + ">";
      });
  m.def(
      "penetration",
      [](const ConvexSet& a, const ConvexSet& b) {
        py::gil_scoped_release release;
        return cvms::penetration(a, b);
      },
      py::arg("a"), py::arg("b"), "The exact penetration depth of a and b (a PenetrationResult).");

  // A few generators (cvms/shapes.hpp), for examples and measurements.
  m.def("cube", [] { return ConvexSet(cvms::shapes::cube()); }, "The cube [-1, 1]^3.");
  m.def("tetrahedron", [] { return ConvexSet(cvms::shapes::tetrahedron()); },
        "The regular tetrahedron (1,1,1), (1,-1,-1), (-1,1,-1), (-1,-1,1).");
  m.def("octahedron", [] { return ConvexSet(cvms::shapes::octahedron()); }, "The octahedron |x|+|y|+|z| <= 1.");
  m.def(
      "box",
      [](py::handle lo, py::handle hi) {
        return ConvexSet(cvms::shapes::box(vec3_from_python(lo, "lo"), vec3_from_python(hi, "hi")));
      },
      py::arg("lo"), py::arg("hi"), "The axis-aligned box [lo, hi] (exact corners).");
  m.def(
      "geodesic_sphere",
      [](int k, bool rotated) {
        py::gil_scoped_release release;
        return ConvexSet(rotated ? cvms::shapes::rotated_geodesic_sphere(k) : cvms::shapes::geodesic_sphere(k));
      },
      py::arg("k"), py::arg("rotated") = false,
      "The benchmark sphere Sphere_k (k = 1..9: about 20 * 4^(k-1) facets), optionally from a rotated "
      "icosahedron (the Sphere_k + rotated Sphere_k benchmark).");
}
