#pragma once
// Counts heap allocations, for the tests that check a hot path (dynamics algorithms, integrator
// steps, simulation steps) allocates nothing once its workspace exists.
//
// allocation_counter.cpp replaces malloc, calloc, realloc and the aligned allocators (forwarding
// to glibc's) with versions that count each call on the calling thread, so Eigen's temporaries
// (aligned_malloc) are counted as well as operator new. Under AddressSanitizer, which owns malloc,
// it replaces only the global `operator new(std::size_t)` (and the matching `operator delete`s).
// A replacement must be defined exactly once per executable, so the definition is built once, as
// the OBJECT library `momenta_allocation_counter` (tests/CMakeLists.txt), and linked into the test
// executables that include this header. It lives in its own translation unit so that GCC does not
// inline it into code it then flags as a mismatched new/delete (-Werror=mismatched-new-delete).
//
// Use: `const long before = test::allocation_count(); <code>; EXPECT_EQ(test::allocation_count()
// - before, 0);`.

namespace momenta::test {

/// Heap allocations made so far on this thread: calls of malloc and its kin (operator new
/// included); under the sanitizers, calls of the global operator new (array, aligned and nothrow
/// forms not counted).
long allocation_count();

/// Whether allocation_count() sees malloc (every build but the sanitizers').
bool allocation_count_includes_malloc();

}  // namespace momenta::test
