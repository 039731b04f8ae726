// What commands report: ordered `key = value` lines, or one JSON object.
#pragma once
#include <string>
#include <vector>

namespace boxlod {

struct KeyValue {
    std::string key;
    std::string value;
    bool number = true;  // quoted in JSON when false
};
using KeyValues = std::vector<KeyValue>;

// Shortest text that reads back to exactly the same double.
std::string format_number(double value);
std::string format_number(float value);  // shortest text for the float
KeyValue number_entry(std::string key, double value);
KeyValue float_entry(std::string key, float value);
KeyValue text_entry(std::string key, std::string value);

// The value of the first entry named `key`, "" when there is none.
std::string value_of(const KeyValues& entries, const std::string& key);

std::string format_key_values(const KeyValues& entries);  // "key = value\n" each
std::string format_json(const KeyValues& entries);        // {"key": value, ...}

}  // namespace boxlod
