#pragma once
// Counts calls of the global operator new, replaced in allocation_counter.cpp (as
// tests/unit/dynamics/allocation_test.cpp does in its own file). The replacement lives in its own
// translation unit so that GCC does not inline it into code it then flags as mismatched.

namespace momenta::test {

/// Global operator new calls made so far on this thread.
long allocation_count();

}  // namespace momenta::test
