#pragma once
// Counts every global operator new in this test executable (allocation_counter.cpp replaces the
// replaceable allocation functions, as the standard allows), so a test can assert that a loop
// allocates nothing.
#include <cstdint>

namespace nimbus::media::test {

std::uint64_t allocationCount();

}  // namespace nimbus::media::test
