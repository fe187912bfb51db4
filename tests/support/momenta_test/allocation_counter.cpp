// The replacements behind allocation_count() (allocation_counter.hpp). Outside the sanitizers
// they count every call of malloc, calloc, realloc and the aligned allocators on the calling
// thread — which is where operator new and Eigen's aligned_malloc both end — and hand the call to
// glibc's own allocator. Under AddressSanitizer the sanitizer owns malloc, so only operator new is
// counted there.
#include "momenta_test/allocation_counter.hpp"

#include <cstdlib>
#include <new>

namespace {
thread_local long allocations = 0;
}  // namespace

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define MOMENTA_COUNT_MALLOC 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer) || \
    __has_feature(memory_sanitizer)
#define MOMENTA_COUNT_MALLOC 0
#endif
#endif
#if !defined(MOMENTA_COUNT_MALLOC) && defined(__GLIBC__)
#define MOMENTA_COUNT_MALLOC 1
#endif
#if !defined(MOMENTA_COUNT_MALLOC)
#define MOMENTA_COUNT_MALLOC 0
#endif

#if MOMENTA_COUNT_MALLOC
// An executable's definitions of these win over the C library's for every library it loads (ELF
// symbol interposition); glibc exports its own under __libc_ names to forward to, and free needs
// no replacement since the memory is glibc's.
extern "C" {
void* __libc_malloc(std::size_t size);
void* __libc_calloc(std::size_t count, std::size_t size);
void* __libc_realloc(void* p, std::size_t size);
void* __libc_memalign(std::size_t alignment, std::size_t size);

void* malloc(std::size_t size) {
  ++allocations;
  return __libc_malloc(size);
}
void* calloc(std::size_t count, std::size_t size) {
  ++allocations;
  return __libc_calloc(count, size);
}
void* realloc(void* p, std::size_t size) {
  ++allocations;
  return __libc_realloc(p, size);
}
void* aligned_alloc(std::size_t alignment, std::size_t size) {
  ++allocations;
  return __libc_memalign(alignment, size);
}
void* memalign(std::size_t alignment, std::size_t size) {
  ++allocations;
  return __libc_memalign(alignment, size);
}
int posix_memalign(void** out, std::size_t alignment, std::size_t size) {
  if (alignment < sizeof(void*) || (alignment & (alignment - 1)) != 0) return 22;  // EINVAL
  ++allocations;
  void* p = __libc_memalign(alignment, size);
  if (p == nullptr) return 12;  // ENOMEM
  *out = p;
  return 0;
}
}
#endif

// operator new ends in malloc, counted above; under the sanitizers it counts itself.
void* operator new(std::size_t size) {
  if constexpr (!MOMENTA_COUNT_MALLOC) ++allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
// The nothrow form too (std::stable_sort's temporary buffer takes it): left to the default, a
// sanitizer's own allocator would hand out the memory that the operator delete here frees with
// free (AddressSanitizer: alloc-dealloc-mismatch).
void* operator new(std::size_t size, const std::nothrow_t&) noexcept {
  if constexpr (!MOMENTA_COUNT_MALLOC) ++allocations;
  return std::malloc(size == 0 ? 1 : size);
}
void operator delete(void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }

namespace momenta::test {

long allocation_count() { return allocations; }

bool allocation_count_includes_malloc() { return MOMENTA_COUNT_MALLOC != 0; }

}  // namespace momenta::test
