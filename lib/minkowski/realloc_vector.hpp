// SPDX-License-Identifier: MIT
// A growable array of trivially copyable elements that grows with realloc.
//
// Why not std::vector: a vector grows by allocating a new block, copying and
// freeing the old one, so at every doubling it touches the whole array again
// and, for large arrays, pages in fresh memory for all of it. The facet lists
// of a sum grow to hundreds of megabytes before the output budget can refuse
// a hostile pair (docs/errors.md, the perpendicular prisms): there, the copies
// and their page faults would be 40 % of the time. realloc of a block that was
// mapped on its own (every large block on glibc) moves its pages with mremap,
// without copying or touching them; elsewhere it is no worse than a vector.
// Only the operations the facet builder needs.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <initializer_list>
#include <new>
#include <type_traits>
#include <utility>

namespace cvms::detail {

template <typename T>
class ReallocVector {
  static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>,
                "elements are moved by realloc, bytewise");

 public:
  ReallocVector() = default;
  ReallocVector(std::initializer_list<T> values) { append(values.begin(), values.end()); }
  ReallocVector(const ReallocVector& other) { append(other.begin(), other.end()); }
  ReallocVector(ReallocVector&& other) noexcept
      : data_(std::exchange(other.data_, nullptr)),
        size_(std::exchange(other.size_, 0)),
        capacity_(std::exchange(other.capacity_, 0)) {}
  ReallocVector& operator=(ReallocVector other) noexcept {
    std::swap(data_, other.data_);
    std::swap(size_, other.size_);
    std::swap(capacity_, other.capacity_);
    return *this;
  }
  ~ReallocVector() { std::free(data_); }

  [[nodiscard]] std::size_t size() const noexcept { return size_; }
  [[nodiscard]] const T* data() const noexcept { return data_; }
  [[nodiscard]] const T* begin() const noexcept { return data_; }
  [[nodiscard]] const T* end() const noexcept { return data_ + size_; }
  [[nodiscard]] const T& operator[](std::size_t i) const noexcept { return data_[i]; }

  void push_back(const T& value) {
    if (size_ == capacity_) grow(size_ + 1);
    data_[size_++] = value;
  }

  /// Appends [first, last), which must not point into this array.
  void append(const T* first, const T* last) {
    const auto n = static_cast<std::size_t>(last - first);
    if (n == 0) return;
    if (capacity_ - size_ < n) grow(size_ + n);
    std::memcpy(static_cast<void*>(data_ + size_), first, n * sizeof(T));
    size_ += n;
  }

 private:
  void grow(std::size_t needed) {
    constexpr std::size_t max_elements = static_cast<std::size_t>(-1) / 2 / sizeof(T);
    if (needed > max_elements) throw std::bad_alloc();
    const std::size_t capacity = std::max({needed, 2 * capacity_, std::size_t{16}});
    void* grown = std::realloc(static_cast<void*>(data_), std::min(capacity, max_elements) * sizeof(T));
    if (grown == nullptr) throw std::bad_alloc();
    data_ = static_cast<T*>(grown);
    capacity_ = std::min(capacity, max_elements);
  }

  T* data_ = nullptr;
  std::size_t size_ = 0;
  std::size_t capacity_ = 0;
};

}  // namespace cvms::detail
