// CSV as RFC 4180 writes it: a field holding a comma, a quote or a line break
// goes in quotes, its quotes doubled; fields are separated by commas. Every
// CSV boxlod writes (sweep results, city frames, timings) goes through here.
#pragma once
#include "base/input_error.h"

#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace boxlod {

std::string csv_row(const std::vector<std::string>& fields);  // one line, without its line break

// The fields of one line csv_row wrote.
std::vector<std::string> csv_fields(std::string_view line);
// "" when `text` may be a text field (UTF-8 without control characters), else what is wrong.
std::string csv_text_problem(const std::string& text);

// Tables boxlod writes and reads back (a sweep's results and timings) are
// input like any other (docs/testing.md: Hardening): what each column holds.
enum class CsvValue {
    text,             // any text
    count,            // a non-negative integer below 2^64
    number,           // a finite number >= 0
    optional_number,  // empty, or a finite number >= 0
    metric,           // a number within its column's range, which may reach inf (PSNR of equal images)
};
struct CsvColumn {
    std::string name;
    CsvValue value = CsvValue::text;
    // A metric's values: by default any but -inf and NaN.
    NumberRange range{std::numeric_limits<double>::lowest(), std::numeric_limits<double>::infinity()};
};
struct CsvRecord {
    int line = 0;  // 1-based, the header being line 1
    std::vector<std::string> fields;
};
constexpr std::size_t max_csv_field_bytes = 4096;

// The rows of `text` under the header `columns` (after a header equal to
// theirs; an empty text has none). Throws InputError "file: line N: COLUMN:
// what" for a row with another field count, a field too long or not of its
// column's kind, and "file: ..." for a header that differs.
std::vector<CsvRecord> read_csv_table(std::string_view text, const std::string& file,
                                      const std::vector<CsvColumn>& columns);

}  // namespace boxlod
