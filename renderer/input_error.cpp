#include "renderer/input_error.h"

namespace boxlod {

std::string input_message(const std::string& file, const std::string& place, const std::string& what) {
    std::string message = file;
    if (!place.empty()) message += ": " + place;
    message += ": " + what;
    for (char& c : message)
        if (c == '\n' || c == '\r') c = ' ';
    while (!message.empty() && message.back() == ' ') message.pop_back();
    return message;
}

}  // namespace boxlod
