// A vector that keeps its first N elements inside itself and goes to the heap only beyond them. A
// solid's faces are mostly triangles and quads with one ring: with std::vector each face cost three
// allocations (rings, vertices, edges), scattered over the heap; with SmallVector it costs none, and a
// face's data sits in one place. The interface is the part of std::vector's the code uses, with pointer
// iterators, so standard algorithms apply unchanged.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <initializer_list>
#include <iterator>
#include <memory>
#include <new>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

namespace hlr {

template <typename T, std::size_t N>
class SmallVector {
  static_assert(N > 0, "SmallVector needs room for at least one element inside");

 public:
  using value_type = T;
  using size_type = std::size_t;
  using difference_type = std::ptrdiff_t;
  using reference = T&;
  using const_reference = const T&;
  using pointer = T*;
  using const_pointer = const T*;
  using iterator = T*;
  using const_iterator = const T*;
  using reverse_iterator = std::reverse_iterator<iterator>;
  using const_reverse_iterator = std::reverse_iterator<const_iterator>;

  SmallVector() noexcept = default;
  SmallVector(std::initializer_list<T> items) { append(items.begin(), items.end()); }
  template <typename It, typename = std::enable_if_t<!std::is_integral_v<It>>>
  SmallVector(It first, It last) {
    append(first, last);
  }
  explicit SmallVector(size_type n, const T& value = T()) { resize(n, value); }
  SmallVector(const std::vector<T>& v) { append(v.begin(), v.end()); }  // NOLINT: as a vector converts
  SmallVector(const SmallVector& other) { append(other.begin(), other.end()); }
  SmallVector(SmallVector&& other) noexcept(std::is_nothrow_move_constructible_v<T>) { take(other); }
  ~SmallVector() { release(); }

  SmallVector& operator=(const SmallVector& other) {
    if (this != &other) assign(other.begin(), other.end());
    return *this;
  }
  SmallVector& operator=(SmallVector&& other) noexcept(std::is_nothrow_move_constructible_v<T>) {
    if (this != &other) {
      release();
      take(other);
    }
    return *this;
  }
  SmallVector& operator=(std::initializer_list<T> items) {
    assign(items.begin(), items.end());
    return *this;
  }
  SmallVector& operator=(const std::vector<T>& v) {
    assign(v.begin(), v.end());
    return *this;
  }

  template <typename It, typename = std::enable_if_t<!std::is_integral_v<It>>>
  void assign(It first, It last) {
    clear();
    append(first, last);
  }
  void assign(size_type n, const T& value) {
    clear();
    resize(n, value);
  }
  void assign(std::initializer_list<T> items) { assign(items.begin(), items.end()); }

  size_type size() const noexcept { return size_; }
  bool empty() const noexcept { return size_ == 0; }
  size_type capacity() const noexcept { return capacity_; }
  T* data() noexcept { return data_; }
  const T* data() const noexcept { return data_; }
  iterator begin() noexcept { return data_; }
  iterator end() noexcept { return data_ + size_; }
  const_iterator begin() const noexcept { return data_; }
  const_iterator end() const noexcept { return data_ + size_; }
  const_iterator cbegin() const noexcept { return data_; }
  const_iterator cend() const noexcept { return data_ + size_; }
  reverse_iterator rbegin() noexcept { return reverse_iterator(end()); }
  reverse_iterator rend() noexcept { return reverse_iterator(begin()); }
  const_reverse_iterator rbegin() const noexcept { return const_reverse_iterator(end()); }
  const_reverse_iterator rend() const noexcept { return const_reverse_iterator(begin()); }
  T& operator[](size_type i) { return data_[i]; }
  const T& operator[](size_type i) const { return data_[i]; }
  const T& at(size_type i) const {
    if (i >= size_) throw std::out_of_range("SmallVector::at");
    return data_[i];
  }
  T& front() { return data_[0]; }
  const T& front() const { return data_[0]; }
  T& back() { return data_[size_ - 1]; }
  const T& back() const { return data_[size_ - 1]; }

  void reserve(size_type n) {
    if (n > capacity_) reallocate(n);
  }
  void clear() noexcept {
    std::destroy(begin(), end());
    size_ = 0;
  }
  void push_back(const T& value) { emplace_back(value); }
  void push_back(T&& value) { emplace_back(std::move(value)); }
  template <typename... Args>
  T& emplace_back(Args&&... args) {
    if (size_ == capacity_) {
      // The argument may be an element of this vector: build the new one before moving the old ones.
      T made(std::forward<Args>(args)...);
      reallocate(grown(size_ + 1));
      ::new (static_cast<void*>(data_ + size_)) T(std::move(made));
    } else {
      ::new (static_cast<void*>(data_ + size_)) T(std::forward<Args>(args)...);
    }
    return data_[size_++];
  }
  void pop_back() {
    std::destroy_at(data_ + size_ - 1);
    --size_;
  }
  void resize(size_type n) {
    if (n < size_) {
      std::destroy(begin() + n, end());
    } else {
      reserve(n);
      std::uninitialized_value_construct(end(), begin() + n);
    }
    size_ = static_cast<std::uint32_t>(n);
  }
  void resize(size_type n, const T& value) {
    if (n < size_) {
      std::destroy(begin() + n, end());
    } else if (n > size_) {
      if (n > capacity_) {
        const T copy = value;  // value may be an element
        reallocate(grown(n));
        std::uninitialized_fill(end(), begin() + n, copy);
      } else {
        std::uninitialized_fill(end(), begin() + n, value);
      }
    }
    size_ = static_cast<std::uint32_t>(n);
  }

  // Inserts [first, last) before pos; the range must not be part of this vector.
  template <typename It, typename = std::enable_if_t<!std::is_integral_v<It>>>
  iterator insert(const_iterator pos, It first, It last) {
    const auto at = static_cast<size_type>(pos - begin());
    const size_type old = size_;
    append(first, last);
    std::rotate(begin() + at, begin() + old, end());
    return begin() + at;
  }
  iterator insert(const_iterator pos, std::initializer_list<T> items) {
    return insert(pos, items.begin(), items.end());
  }
  iterator insert(const_iterator pos, const T& value) {
    const auto at = static_cast<size_type>(pos - begin());
    emplace_back(value);
    std::rotate(begin() + at, end() - 1, end());
    return begin() + at;
  }
  iterator erase(const_iterator first, const_iterator last) {
    const auto a = static_cast<size_type>(first - begin()), b = static_cast<size_type>(last - begin());
    std::move(begin() + b, end(), begin() + a);
    std::destroy(end() - (b - a), end());
    size_ -= static_cast<std::uint32_t>(b - a);
    return begin() + a;
  }
  iterator erase(const_iterator pos) { return erase(pos, pos + 1); }

  friend bool operator==(const SmallVector& a, const SmallVector& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end());
  }
  friend bool operator==(const SmallVector& a, const std::vector<T>& b) {
    return std::equal(a.begin(), a.end(), b.begin(), b.end());
  }

 private:
  bool is_inline() const noexcept { return data_ == inline_data(); }
  T* inline_data() noexcept { return std::launder(reinterpret_cast<T*>(inline_)); }
  const T* inline_data() const noexcept { return std::launder(reinterpret_cast<const T*>(inline_)); }
  size_type grown(size_type need) const { return std::max<size_type>(need, 2 * size_type{capacity_}); }

  template <typename It>
  void append(It first, It last) {
    if constexpr (std::is_base_of_v<std::forward_iterator_tag,
                                    typename std::iterator_traits<It>::iterator_category>) {
      const auto n = static_cast<size_type>(std::distance(first, last));
      if (size_ + n > capacity_) reallocate(grown(size_ + n));
      std::uninitialized_copy(first, last, end());
      size_ += static_cast<std::uint32_t>(n);
    } else {
      for (; first != last; ++first) emplace_back(*first);
    }
  }

  // Moves the elements to a heap block of `n` (≥ size) elements.
  void reallocate(size_type n) {
    if (n > 0xffffffffu) throw std::length_error("SmallVector: too many elements");
    T* block = static_cast<T*>(::operator new(n * sizeof(T), std::align_val_t{alignof(T)}));
    std::uninitialized_move(begin(), end(), block);
    std::destroy(begin(), end());
    if (!is_inline()) ::operator delete(data_, std::align_val_t{alignof(T)});
    data_ = block;
    capacity_ = static_cast<std::uint32_t>(n);
  }

  // Takes other's elements (its block if on the heap), leaving it empty and inline.
  void take(SmallVector& other) {
    if (other.is_inline()) {
      data_ = inline_data();
      capacity_ = N;
      std::uninitialized_move(other.begin(), other.end(), data_);
      size_ = other.size_;
      other.clear();
    } else {
      data_ = other.data_;
      size_ = other.size_;
      capacity_ = other.capacity_;
      other.data_ = other.inline_data();
      other.size_ = 0;
      other.capacity_ = N;
    }
  }

  void release() noexcept {
    clear();
    if (!is_inline()) ::operator delete(data_, std::align_val_t{alignof(T)});
    data_ = inline_data();
    capacity_ = N;
  }

  T* data_ = inline_data();
  std::uint32_t size_ = 0;
  std::uint32_t capacity_ = N;
  alignas(T) unsigned char inline_[N * sizeof(T)];
};

}  // namespace hlr
