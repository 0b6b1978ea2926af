#pragma once
// An allocator for the octree's big arrays (millions of nodes, shapes, codes).
// Buffers of 2 MiB and more are aligned to 2 MiB and offered to the kernel
// as transparent huge pages (madvise), which Debian enables only on request:
// first touching a 4 KiB page costs a page fault, and on a virtual machine
// those faults were most of the build time of a 16M-point octree (6.2 s of
// build against 1.9 s with huge pages). Small buffers come from the heap,
// aligned as their type asks (octree nodes are cache-line aligned).

#include <cstddef>
#include <new>
#include <string>
#include <vector>

namespace occlusion {

namespace large_buffer_detail {
void* allocate(std::size_t bytes, std::size_t alignment);
void deallocate(void* p) noexcept;
}  // namespace large_buffer_detail

// Offers the whole huge pages inside [p, p + bytes) to the kernel as such:
// for big buffers that are not LargeVectors (a cloud's positions, a
// std::vector every layer passes around). Only advice; nothing below 2 MiB.
void advise_huge_pages(void* p, std::size_t bytes) noexcept;

template <class T>
struct LargeBufferAllocator {
  using value_type = T;
  LargeBufferAllocator() = default;
  template <class U>
  LargeBufferAllocator(const LargeBufferAllocator<U>&) noexcept {}  // NOLINT: rebinding

  T* allocate(std::size_t count) {
    if (count > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_alloc();
    return static_cast<T*>(large_buffer_detail::allocate(count * sizeof(T), alignof(T)));
  }
  void deallocate(T* p, std::size_t) noexcept { large_buffer_detail::deallocate(p); }

  template <class U>
  bool operator==(const LargeBufferAllocator<U>&) const noexcept {
    return true;
  }
  template <class U>
  bool operator!=(const LargeBufferAllocator<U>&) const noexcept {
    return false;
  }
};

template <class T>
using LargeVector = std::vector<T, LargeBufferAllocator<T>>;
using LargeString = std::basic_string<char, std::char_traits<char>, LargeBufferAllocator<char>>;

}  // namespace occlusion
