#include "toolkit/selection/strategy_text.h"

#include "base/input_error.h"
#include "base/key_values.h"
#include "base/number_text.h"

#include <cmath>

namespace boxlod {
namespace {

std::vector<std::string> split_commas(const std::string& text) {
    std::vector<std::string> parts;
    std::size_t begin = 0;
    for (;;) {
        std::size_t comma = text.find(',', begin);
        parts.push_back(text.substr(begin, comma - begin));
        if (comma == std::string::npos) return parts;
        begin = comma + 1;
    }
}

double parse_number(const std::string& text, const std::string& where, const std::string& strategy) {
    const auto value = finite_number<double>(text);
    if (!value) throw_input_error(where, strategy, "expected a number, got '" + text + "'");
    return *value;
}

std::vector<double> parse_numbers(const std::vector<std::string>& parts, const std::string& where,
                                  const std::string& strategy) {
    std::vector<double> numbers;
    for (const std::string& part : parts) numbers.push_back(parse_number(part, where, strategy));
    return numbers;
}

std::string join_numbers(const std::vector<double>& numbers) {
    std::string out;
    for (double n : numbers)
        out.append(out.empty() ? "" : ",")
            .append(format_number(n));  // not "," + ...: GCC 12's false -Wrestrict
    return out;
}

const char* interpolation_text(DiagonalInterpolation interpolation) {
    switch (interpolation) {
    case DiagonalInterpolation::square: return "square";
    case DiagonalInterpolation::square_root: return "square-root";
    case DiagonalInterpolation::linear: break;
    }
    return "linear";
}

// diagonal[:MIN,MAX[,INTERPOLATION]], its arguments split at the commas.
BoxDiagonal parse_diagonal(const std::vector<std::string>& parts, const std::string& where) {
    BoxDiagonal diagonal;
    if (parts.empty()) return diagonal;
    if (parts.size() < 2 || parts.size() > 3)
        throw_input_error(where, "diagonal", "expected diagonal:MIN,MAX[,linear|square|square-root]");
    diagonal.min_pixels = parse_number(parts[0], where, "diagonal");
    diagonal.max_pixels = parse_number(parts[1], where, "diagonal");
    if (parts.size() == 3) {
        const std::string& mode = parts[2];
        if (mode == "linear")
            diagonal.interpolation = DiagonalInterpolation::linear;
        else if (mode == "square")
            diagonal.interpolation = DiagonalInterpolation::square;
        else if (mode == "square-root")
            diagonal.interpolation = DiagonalInterpolation::square_root;
        else
            throw_input_error(where, "diagonal",
                              "unknown interpolation '" + mode + "' (linear, square, square-root)");
    }
    return diagonal;
}

}  // namespace

Strategy parse_strategy(const std::string& text, const std::string& where) {
    std::size_t colon = text.find(':');
    std::string name = text.substr(0, colon);
    bool has_arguments = colon != std::string::npos;
    std::vector<std::string> parts =
        has_arguments ? split_commas(text.substr(colon + 1)) : std::vector<std::string>{};
    auto thresholds = [&](const char* example) {
        if (!has_arguments)
            throw_input_error(where, name, std::string("needs thresholds, e.g. '") + example + "'");
        return parse_numbers(parts, where, name);
    };
    auto one_number = [&](const char* value_name) {  // NAME:VALUE
        if (parts.size() != 1)
            throw_input_error(where, name, "expected " + name + " or " + name + ":" + value_name);
        return parse_number(parts[0], where, name);
    };
    Strategy strategy;
    if (name == "distance") {
        strategy = DistanceBands{thresholds("distance:40,80,160")};
    } else if (name == "pixels") {
        strategy = PixelCount{thresholds("pixels:200000,50000,10000")};
    } else if (name == "ratio") {
        strategy = ScreenRatio{thresholds("ratio:0.2,0.05,0.01")};
    } else if (name == "diagonal") {
        strategy = parse_diagonal(parts, where);
    } else if (name == "texel") {
        TexelExact texel;
        if (has_arguments) texel.error_budget = one_number("ERROR_BUDGET");
        strategy = texel;
    } else if (name == "measured") {
        MeasuredSwitch measured;
        if (has_arguments) measured.error = one_number("ERROR");
        strategy = measured;
    } else {
        throw_input_error(where, "",
                          "unknown strategy '" + text +
                              "' (distance:D1,D2,..., pixels:P1,P2,..., ratio:R1,R2,..., "
                              "diagonal[:MIN,MAX[,INTERPOLATION]], texel[:BUDGET], measured[:ERROR])");
    }
    validate_strategy(strategy, where);
    return strategy;
}

std::string strategy_name(const Strategy& strategy) {
    static const char* const names[] = {"distance", "pixels", "ratio", "diagonal", "texel", "measured"};
    return names[strategy.index()];
}

std::string format_strategy(const Strategy& strategy) {
    std::string name = strategy_name(strategy);
    if (auto* s = std::get_if<DistanceBands>(&strategy)) return name + ":" + join_numbers(s->distances);
    if (auto* s = std::get_if<PixelCount>(&strategy)) return name + ":" + join_numbers(s->pixels);
    if (auto* s = std::get_if<ScreenRatio>(&strategy)) return name + ":" + join_numbers(s->ratios);
    if (auto* s = std::get_if<BoxDiagonal>(&strategy))
        return name + ":" + join_numbers({s->min_pixels, s->max_pixels}) + "," +
               interpolation_text(s->interpolation);
    if (auto* s = std::get_if<MeasuredSwitch>(&strategy)) return name + ":" + format_number(s->error);
    const TexelExact& texel = std::get<TexelExact>(strategy);
    return texel.error_budget ? name + ":" + format_number(*texel.error_budget) : name;
}

}  // namespace boxlod
