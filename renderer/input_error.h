// Bad input of any kind: a one-line message that names the file and the place.
// The CLI prints it and exits with status 2 (DESIGN.md: Errors).
#pragma once
#include <stdexcept>
#include <string>

namespace boxlod {

struct InputError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// "file: what" or "file: place: what", squeezed onto one line.
std::string input_message(const std::string& file, const std::string& place, const std::string& what);

[[noreturn]] inline void throw_input_error(const std::string& file, const std::string& place,
                                           const std::string& what) {
    throw InputError(input_message(file, place, what));
}

}  // namespace boxlod
