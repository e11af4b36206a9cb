// The one entry point every fuzz target defines (libFuzzer's signature).
//
// Each *_fuzz.cpp file in this folder is built twice: with clang's
// -fsanitize=fuzzer into a libFuzzer binary (CASTELJAU_FUZZ=ON), and with
// replay_main.cpp into a plain program that the test suite runs over the
// seed corpus and every input a fuzzer ever crashed on (regressions/).
#pragma once

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);
