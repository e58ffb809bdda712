// One libFuzzer target: NIMBUS_FUZZ_ENTRY names the entry of fuzz_entries.h it feeds.
#include <cstddef>
#include <cstdint>

#include "fuzz_entries.h"
#include "nimbus/base/log.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
    nimbus::log::setLevel(nimbus::log::Level::Off);  // warnings about accepted input would drown the fuzzer's output
    return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    nimbus::fuzz::NIMBUS_FUZZ_ENTRY(data, size);
    return 0;
}
