// A vector of at most N elements stored inside the object: the exact CCD's polynomials have
// degree <= 4, so their coefficients, Sturm sequences and roots have known small bounds, and
// keeping them inline spares an allocation per polynomial. Exceeding N is a bug: it throws
// std::length_error. Private to reference/.
#pragma once

#include <array>
#include <cstddef>
#include <initializer_list>
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
  // Copies and moves touch the n elements in use only.
  InlineVector(const InlineVector& o) { *this = o; }
  InlineVector(InlineVector&& o) noexcept { *this = std::move(o); }
  InlineVector& operator=(const InlineVector& o) {
    if (this != &o) {
      for (std::size_t i = 0; i < o.n_; ++i) v_[i] = o.v_[i];
      n_ = o.n_;
    }
    return *this;
  }
  InlineVector& operator=(InlineVector&& o) noexcept {
    if (this != &o) {
      for (std::size_t i = 0; i < o.n_; ++i) v_[i] = std::move(o.v_[i]);
      n_ = o.n_;
    }
    return *this;
  }

  std::size_t size() const { return n_; }
  bool empty() const { return n_ == 0; }
  T& operator[](std::size_t i) { return v_[i]; }
  const T& operator[](std::size_t i) const { return v_[i]; }
  T& back() { return v_[n_ - 1]; }
  const T& back() const { return v_[n_ - 1]; }
  T* begin() { return v_.data(); }
  T* end() { return v_.data() + n_; }
  const T* begin() const { return v_.data(); }
  const T* end() const { return v_.data() + n_; }

  void push_back(T x) {
    if (n_ == N) throw std::length_error("InlineVector: more than its capacity");
    v_[n_++] = std::move(x);
  }
  void pop_back() { --n_; }
  void resize(std::size_t n) {  // new elements are T()
    if (n > N) throw std::length_error("InlineVector: more than its capacity");
    for (std::size_t i = n_; i < n; ++i) v_[i] = T();
    n_ = n;
  }

 private:
  std::array<T, N> v_{};
  std::size_t n_ = 0;
};

}  // namespace fdh::exact::algebra
