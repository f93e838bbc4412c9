#pragma once
// A std::vector whose resize() leaves new elements of trivial types unset (default-initialised)
// instead of zeroing them. For large arrays that a parallel loop fills next: a zeroing resize runs
// on one thread and takes the page faults of the whole array there (first touch), which made the
// neighbour list's buffers a serial part of every build (bench/RESULTS.md, analysis/atoms).
// Arrays of 4 MB and more are also marked for transparent huge pages (madvise; the kernel's
// default mode on Debian), so that first touch takes one fault per 2 MB instead of per 4 kB.
#include <sys/mman.h>

#include <cstdint>
#include <memory>
#include <vector>

namespace shockfield {

template <class T, class Base = std::allocator<T>>
struct DefaultInitAllocator : Base {
  using Base::Base;
  T* allocate(std::size_t n) {
    T* p = std::allocator_traits<Base>::allocate(static_cast<Base&>(*this), n);
    constexpr std::size_t kPage = 4096, kLarge = std::size_t{4} << 20;
    if (n * sizeof(T) >= kLarge) {
      const auto begin = (reinterpret_cast<std::uintptr_t>(p) + kPage - 1) & ~(kPage - 1);
      const auto end = (reinterpret_cast<std::uintptr_t>(p) + n * sizeof(T)) & ~(kPage - 1);
      madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);  // a hint: failure changes nothing
    }
    return p;
  }
  template <class U>
  struct rebind {
    using other = DefaultInitAllocator<U, typename std::allocator_traits<Base>::template rebind_alloc<U>>;
  };
  /// Value-initialisation without arguments becomes default-initialisation (no zeroing).
  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    std::allocator_traits<Base>::construct(static_cast<Base&>(*this), p, std::forward<Args>(args)...);
  }
};

template <class T>
using UninitializedVector = std::vector<T, DefaultInitAllocator<T>>;

}  // namespace shockfield
