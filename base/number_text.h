// Numbers written in files and on command lines, read whole: "12", "0.25",
// "1e-3". No spaces, no '+', no trailing text (std::from_chars' grammar).
#pragma once
#include "base/input_error.h"

#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>

namespace boxlod {

// All of `text` as a Number; false if any of it is not one (inf and nan read).
template <typename Number>
bool read_whole(std::string_view text, Number& value) {
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    return error == std::errc() && end == text.data() + text.size();
}

// All of `text` as a finite Number; nothing otherwise.
template <typename Number>
std::optional<Number> finite_number(std::string_view text) {
    Number value{};
    if (!read_whole(text, value) || !std::isfinite(double(value))) return std::nullopt;
    return value;
}

// Whether `value` is held by a Number as a normal number or 0: 1e-46 as a
// float would be read as 0, 1e39 as inf.
template <typename Number>
bool representable(double value) {
    return !std::is_floating_point_v<Number> || value == 0 || std::isnormal(Number(value));
}

// All of `text` as a Number within `range`; nothing otherwise. A float is
// checked as the double written: 0.01 read as a float lies below 0.01.
template <typename Number>
std::optional<Number> number_within(std::string_view text, const NumberRange& range) {
    const auto value =
        finite_number<std::conditional_t<std::is_floating_point_v<Number>, double, Number>>(text);
    if (!value || !range.contains(double(*value)) || !representable<Number>(double(*value)))
        return std::nullopt;
    return Number(*value);
}

// All of `text` as a count (a whole decimal number); else throws InputError
// naming `file` and `place`: "expected a count, got 'TEXT'".
inline std::size_t read_count(std::string_view text, const std::string& file, const std::string& place) {
    std::size_t value = 0;
    if (!read_whole(text, value))
        throw_input_error(file, place, "expected a count, got '" + std::string(text) + "'");
    return value;
}

// A type's limit as a message gives it: "1.2e-38".
inline std::string format_limit(double value) {
    char text[16];
    std::snprintf(text, sizeof text, "%.2g", value);
    return text;
}

// What is wrong with `text` as a Number within `range`; "" if nothing.
// "expected a whole number in [min, max], got '2.5'" for a fraction where a
// whole number is read, else out_of_range_message.
template <typename Number>
std::string number_problem(std::string_view text, const NumberRange& range) {
    if (number_within<Number>(text, range)) return "";
    // (Not for a whole number outside the range: 99999999999 is a number outside [1, 64].)
    if (const auto written = finite_number<double>(text);
        std::is_integral_v<Number> && written &&
        (*written != std::floor(*written) || range.contains(*written)))
        return "expected a whole number in " + range_text(range) + ", got '" + std::string(text) + "'";
    if (const auto written = finite_number<double>(text);
        written && range.contains(*written) && !representable<Number>(*written))
        return "expected 0 or a number of magnitude in [" + format_limit(std::numeric_limits<Number>::min()) +
               ", " + format_limit(std::numeric_limits<Number>::max()) + "], got '" + std::string(text) + "'";
    return out_of_range_message(range, std::string(text));
}

}  // namespace boxlod
