// What commands report: ordered `key = value` lines, or one JSON object.
#pragma once
#include <string>
#include <string_view>
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
KeyValue numbers_entry(std::string key,
                       const std::vector<double>& values);  // "v1,v2,...", each read back exactly

// The value of the first entry named `key`, "" when there is none.
std::string value_of(const KeyValues& entries, const std::string& key);

// The items of a comma-separated value ("0.5, 0.25" in a file, "10,20" after
// an option), blanks around each trimmed. Every comma separates, so "a,",
// ",a", "a,,b" and "" hold empty items, which each list's parser refuses.
std::vector<std::string> comma_list(std::string_view text);

std::string format_key_values(const KeyValues& entries);  // "key = value\n" each
std::string format_json(const KeyValues& entries);        // {"key": value, ...}

}  // namespace boxlod
