// One libFuzzer target per reader of untrusted bytes (`make fuzz`; docs/testing.md:
// Hardening). Each target feeds the bytes to the reader: an InputError is the
// right answer to bad input; anything else (a crash, a sanitizer report, any
// other exception, a hang) is a bug. In every other build the same target is
// linked with replay_main.cpp and replays its corpus as a test.
#pragma once
#include "base/input_error.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace boxlod::fuzz {

inline std::string text(const std::uint8_t* data, std::size_t size) {
    return {reinterpret_cast<const char*>(data), size};
}

// Runs read(); swallows only InputError.
template <typename Read>
int expect_only_input_errors(Read read) {
    try {
        read();
    } catch (const InputError&) {
    }
    return 0;
}

}  // namespace boxlod::fuzz
