#include "base/csv.h"

#include "base/input_error.h"
#include "base/number_text.h"

#include <cmath>
#include <cstdint>

namespace boxlod {

std::string csv_row(const std::vector<std::string>& fields) {
    std::string line;
    for (std::size_t i = 0; i < fields.size(); ++i) {
        if (i > 0) line += ',';
        const std::string& field = fields[i];
        if (field.find_first_of(",\"\r\n") == std::string::npos) {
            line += field;
            continue;
        }
        line += '"';
        for (char c : field) line += c == '"' ? std::string("\"\"") : std::string(1, c);
        line += '"';
    }
    return line;
}

std::vector<std::string> csv_fields(std::string_view line) {
    std::vector<std::string> fields(1);
    bool quoted = false;
    for (std::size_t i = 0; i < line.size(); ++i) {
        char c = line[i];
        if (quoted && c == '"' && i + 1 < line.size() && line[i + 1] == '"') {
            fields.back() += '"';
            ++i;
        } else if (c == '"') {
            quoted = !quoted;
        } else if (c == ',' && !quoted) {
            fields.emplace_back();
        } else {
            fields.back() += c;
        }
    }
    return fields;
}

namespace {

bool is_count(const std::string& field) {
    std::uint64_t value = 0;
    return read_whole(field, value);
}

}  // namespace

std::string csv_text_problem(const std::string& text) {
    for (std::size_t i = 0; i < text.size();) {
        const auto byte = static_cast<unsigned char>(text[i]);
        if (byte < 0x20 || byte == 0x7f) return "a control character (byte " + std::to_string(byte) + ")";
        // A lead byte and its continuation bytes (RFC 3629: C0, C1 and F5-FF never occur).
        const int length = byte < 0x80                    ? 1
                           : byte >= 0xc2 && byte <= 0xdf ? 2
                           : byte >= 0xe0 && byte <= 0xef ? 3
                           : byte >= 0xf0 && byte <= 0xf4 ? 4
                                                          : 0;
        if (length == 0 || i + std::size_t(length) > text.size()) return "bytes that are not UTF-8";
        for (int k = 1; k < length; ++k)
            if ((static_cast<unsigned char>(text[i + std::size_t(k)]) & 0xc0) != 0x80)
                return "bytes that are not UTF-8";
        // The second byte's range where the lead allows less: no overlong form, nothing past U+10FFFF; C1
        // controls.
        const auto second = length > 1 ? static_cast<unsigned char>(text[i + 1]) : 0;
        if ((byte == 0xe0 && second < 0xa0) || (byte == 0xf0 && second < 0x90) ||
            (byte == 0xf4 && second > 0x8f))
            return "bytes that are not UTF-8";
        if (byte == 0xc2 && second < 0xa0) return "a control character (U+0080 to U+009F)";
        i += std::size_t(length);
    }
    return "";
}

namespace {

// "" when `field` is of `kind`, else what is wrong.
std::string field_problem(const std::string& field, CsvValue kind, const NumberRange& range) {
    if (field.size() > max_csv_field_bytes)
        return "a field of " + std::to_string(field.size()) + " bytes (at most " +
               std::to_string(max_csv_field_bytes) + ")";
    double value = 0;
    switch (kind) {
    case CsvValue::text: return csv_text_problem(field);
    case CsvValue::count:
        return is_count(field) ? "" : "'" + field + "' is not a count (a whole number >= 0)";
    case CsvValue::optional_number:
        if (field.empty()) return "";
        [[fallthrough]];
    case CsvValue::number:
        return read_whole(field, value) && std::isfinite(value) && value >= 0
                   ? ""
                   : "'" + field + "' is not a finite number >= 0";
    case CsvValue::metric:
        return read_whole(field, value) && range.contains(value)
                   ? ""
                   : "'" + field + "' is not a metric value in " + range_text(range);
    }
    return "";
}

}  // namespace

std::vector<CsvRecord> read_csv_table(std::string_view text, const std::string& file,
                                      const std::vector<CsvColumn>& columns) {
    std::vector<std::string> names;
    for (const CsvColumn& column : columns) names.push_back(column.name);
    const std::string header = csv_row(names);
    std::vector<CsvRecord> records;
    std::size_t start = 0;
    for (int number = 1; start < text.size(); ++number) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        const std::string_view line = text.substr(start, end - start);
        start = end + 1;
        const std::string place = "line " + std::to_string(number);
        if (number == 1) {
            if (line != header)
                throw_input_error(file, "",
                                  "its columns are not " + header + " (a table of another run or kind)");
            continue;
        }
        if (line.empty()) continue;
        if (line.size() > columns.size() * (max_csv_field_bytes + 3))
            throw_input_error(file, place,
                              "a line of " + std::to_string(line.size()) + " bytes, longer than any row");
        std::vector<std::string> fields = csv_fields(line);
        if (fields.size() != columns.size())
            throw_input_error(
                file, place,
                std::to_string(fields.size()) + " fields, not " + std::to_string(columns.size()));
        for (std::size_t k = 0; k < fields.size(); ++k)
            if (std::string problem = field_problem(fields[k], columns[k].value, columns[k].range);
                !problem.empty())
                throw_input_error(file, place + ": " + columns[k].name, problem);
        records.push_back({number, std::move(fields)});
    }
    return records;
}

}  // namespace boxlod
