// A minimal JSON writer for the CLI's machine-readable output: numbers are
// written with enough digits to round-trip, strings escaped per RFC 8259.
#pragma once

#include <string>
#include <string_view>

namespace casteljau::cli {

std::string json_number(double v);
std::string json_string(std::string_view s);

} // namespace casteljau::cli
