#pragma once
// A vector whose first K elements live in place (on the caller's stack) and only more go to the
// heap: the stacks and heaps of the space tree's searches, so that a query allocates nothing in
// the usual case. Just what those need: push_back, pop_back, clear, front/back, [], iteration.
#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace shockfield::geometry {

template <class T, std::size_t K>
class InlineVector {
 public:
  InlineVector() = default;
  InlineVector(const InlineVector&) = delete;  // data_ may point into this object
  InlineVector& operator=(const InlineVector&) = delete;

  void push_back(const T& v) {
    if (size_ == capacity_) grow();
    data_[size_++] = v;
  }
  void pop_back() { --size_; }
  void clear() { size_ = 0; }
  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }
  T& front() { return data_[0]; }
  T& back() { return data_[size_ - 1]; }
  const T& front() const { return data_[0]; }
  const T& back() const { return data_[size_ - 1]; }
  T* begin() { return data_; }
  T* end() { return data_ + size_; }
  const T* begin() const { return data_; }
  const T* end() const { return data_ + size_; }

 private:
  void grow() {
    std::vector<T> bigger(2 * capacity_);
    std::copy(data_, data_ + size_, bigger.begin());
    heap_ = std::move(bigger);
    data_ = heap_.data();
    capacity_ = heap_.size();
  }
  std::array<T, K> local_;  // left uninitialised: only [0, size_) is ever read
  std::vector<T> heap_;
  T* data_ = local_.data();
  std::size_t size_ = 0, capacity_ = K;
};

}  // namespace shockfield::geometry
