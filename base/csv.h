// CSV as RFC 4180 writes it: a field holding a comma, a quote or a line break
// goes in quotes, its quotes doubled; fields are separated by commas. Every
// CSV boxlod writes (sweep results, city frames, timings) goes through here.
#pragma once
#include <string>
#include <string_view>
#include <vector>

namespace boxlod {

std::string csv_row(const std::vector<std::string>& fields);  // one line, without its line break

// The fields of one line csv_row wrote.
std::vector<std::string> csv_fields(std::string_view line);

}  // namespace boxlod
