#include "data_gen/grammar.h"

#include "base/input_error.h"

namespace boxlod {

std::string grammar_message(const std::string& file, SourcePlace place, const std::string& what) {
    std::string message = file + ":" + std::to_string(place.line) + ":" + std::to_string(place.column) + ": " + what;
    for (char& c : message)
        if (c == '\n' || c == '\r') c = ' ';
    return message;
}

void throw_grammar_error(const std::string& file, SourcePlace place, const std::string& what) {
    throw InputError(grammar_message(file, place, what));
}

}  // namespace boxlod
