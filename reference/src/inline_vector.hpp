// A vector of at most N elements stored inside the object: the exact CCD's polynomials have
// degree <= 6, so their coefficients, Sturm sequences and roots have known small bounds, and
// keeping them inline spares an allocation per polynomial. Only the elements in use are
// constructed (a polynomial of degree 1 builds two integers, not five). Exceeding N is a bug:
// it throws std::length_error. Private to reference/.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <new>  // placement new
#include <stdexcept>
#include <utility>

namespace fdh::exact::algebra {

template <class T, std::size_t N>
class InlineVector {
 public:
  InlineVector() = default;
  explicit InlineVector(std::size_t n) { resize(n); }
  InlineVector(std::initializer_list<T> values) {
    for (const T& v : values) push_back(v);
  }
  InlineVector(const InlineVector& o) {
    for (const T& v : o) push_back(v);
  }
  InlineVector(InlineVector&& o) noexcept {
    for (T& v : o) new (slot(n_++)) T(std::move(v));
  }
  InlineVector& operator=(const InlineVector& o) {
    if (this != &o) assign(o, [](const T& v) -> const T& { return v; });
    return *this;
  }
  InlineVector& operator=(InlineVector&& o) noexcept {
    if (this != &o) assign(o, [](T& v) -> T&& { return std::move(v); });
    return *this;
  }
  ~InlineVector() { resize(0); }

  std::size_t size() const { return n_; }
  bool empty() const { return n_ == 0; }
  T& operator[](std::size_t i) { return *slot(i); }
  const T& operator[](std::size_t i) const { return *slot(i); }
  T& back() { return *slot(n_ - 1); }
  const T& back() const { return *slot(n_ - 1); }
  T* begin() { return slot(0); }
  T* end() { return slot(n_); }
  const T* begin() const { return slot(0); }
  const T* end() const { return slot(n_); }

  void push_back(T x) {
    if (n_ == N) throw std::length_error("InlineVector: more than its capacity");
    new (slot(n_)) T(std::move(x));
    ++n_;
  }
  void pop_back() { slot(--n_)->~T(); }
  void resize(std::size_t n) {  // new elements are T()
    if (n > N) throw std::length_error("InlineVector: more than its capacity");
    for (; n_ < n; ++n_) new (slot(n_)) T();
    while (n_ > n) pop_back();
  }

 private:
  // The elements live in storage_, made by placement new.
  T* slot(std::size_t i) { return reinterpret_cast<T*>(storage_) + i; }
  const T* slot(std::size_t i) const { return reinterpret_cast<const T*>(storage_) + i; }
  // Element-wise from o through `pass` (a copy or a move): assigned where both have one,
  // constructed or destroyed for the rest.
  template <class Other, class Pass>
  void assign(Other& o, Pass pass) {
    std::size_t i = 0;
    for (; i < n_ && i < o.n_; ++i) *slot(i) = pass(*o.slot(i));
    for (; i < o.n_; ++i) new (slot(i)) T(pass(*o.slot(i)));
    while (n_ > o.n_) pop_back();
    n_ = o.n_;
  }

  alignas(T) unsigned char storage_[N * sizeof(T)];
  std::size_t n_ = 0;
};

}  // namespace fdh::exact::algebra
