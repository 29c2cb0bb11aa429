// SPDX-License-Identifier: MIT
// Results a command is done with, left to the process's exit instead of
// being freed one by one. An exact polyhedron of 20,000 facets holds about
// 250,000 heap blocks (a limb or two per rational); freeing them would cost
// about a tenth of the instructions of `cvms check sphere6.off`, while the
// kernel takes the whole heap back at exit at once. Compilers do the same
// with what they build (clang's -disable-free).
//
// The objects stay reachable from a static pointer, so valgrind and
// LeakSanitizer count them as reachable, not leaked. The library itself
// never does this: it is the tool's choice, because the tool knows that
// it exits next.
#pragma once

#include <type_traits>
#include <utility>

namespace cvms::cli {

namespace detail {
// Takes ownership of a block whose destructor is never run.
void hold_until_exit(const void* object);
}  // namespace detail

template <class T>
void keep_until_exit(T&& value) {
  detail::hold_until_exit(new std::decay_t<T>(std::forward<T>(value)));
}

}  // namespace cvms::cli
