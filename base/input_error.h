// Bad input of any kind: a one-line message that names the file and the place.
// The CLI prints it and exits with status 2 (docs/design.md: Errors).
#pragma once
#include <cstddef>
#include <stdexcept>
#include <string>

namespace boxlod {

// Its message is made one printable line: line breaks become spaces and other
// control characters \xHH (a NUL in a file's object name ended the line there,
// an ESC reached the terminal), and it is cut after 10,000 bytes.
struct InputError : std::runtime_error {
    explicit InputError(const std::string& message);
};

// "file: what" or "file: place: what", one printable line (for warnings too).
std::string input_message(const std::string& file, const std::string& place, const std::string& what);

[[noreturn]] inline void throw_input_error(const std::string& file, const std::string& place,
                                           const std::string& what) {
    throw InputError(input_message(file, place, what));
}

// Every recursive reader (grammar, expressions, JSON, IFC references) refuses
// input nested deeper than this: far beyond any real file, far within the stack.
constexpr int max_nesting_depth = 200;
std::string nesting_message();  // "nested more than 200 levels deep"

// The values a number from a file or an option may take, both ends included.
struct NumberRange {
    double min, max;
    constexpr bool contains(double value) const { return value >= min && value <= max; }  // false for NaN
};
std::string range_text(const NumberRange& range);  // "[min, max]"
// "expected a number in [min, max], got 'text'"
std::string out_of_range_message(const NumberRange& range, const std::string& text);

// True when [offset, offset + length) lies inside [0, size), without overflow
// for any values read from a file.
constexpr bool range_fits(std::size_t offset, std::size_t length, std::size_t size) {
    return offset <= size && length <= size - offset;
}
// a * b, or false when the product does not fit in size_t.
inline bool checked_multiply(std::size_t a, std::size_t b, std::size_t& product) {
    return !__builtin_mul_overflow(a, b, &product);
}

}  // namespace boxlod
