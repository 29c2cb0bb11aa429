# cmake -DREADME=README.md -DSOURCE=examples/readme.cpp -P readme_check.cmake
# Fails unless the first ```cpp block after "## C++ usage" in README is
# SOURCE without its leading // comment lines: the README's example is the
# program that example.readme compiles and runs.
file(READ "${README}" readme)
file(READ "${SOURCE}" source)
string(FIND "${readme}" "\n## C++ usage\n" at)
if(at EQUAL -1)
  message(FATAL_ERROR "${README} has no \"## C++ usage\" section")
endif()
string(SUBSTRING "${readme}" ${at} -1 section)
string(FIND "${section}" "\n```cpp\n" begin)
if(begin EQUAL -1)
  message(FATAL_ERROR "the \"C++ usage\" section of ${README} has no ```cpp block")
endif()
math(EXPR begin "${begin} + 8")
string(SUBSTRING "${section}" ${begin} -1 section)
string(FIND "${section}" "\n```" end)
math(EXPR end "${end} + 1")
string(SUBSTRING "${section}" 0 ${end} block)
string(REGEX REPLACE "^(//[^\n]*\n)+" "" code "${source}")
if(NOT block STREQUAL code)
  message(FATAL_ERROR "README.md's C++ usage block and ${SOURCE} (below its comment lines) differ; "
                      "README:\n${block}\n${SOURCE}:\n${code}")
endif()
