#include "data_gen/expression.h"

#include <cmath>
#include <numbers>

namespace boxlod {

namespace {

struct Function {
    const char* name;
    int arity;
};
constexpr Function functions[] = {{"rand", 2}, {"min", 2},   {"max", 2}, {"floor", 1},
                                  {"ceil", 1}, {"round", 1}, {"abs", 1}, {"sqrt", 1},
                                  {"sin", 1},  {"cos", 1},   {"tan", 1}};

double degrees(double value) { return value * std::numbers::pi / 180; }

double call(const Expression& e, const std::vector<double>& a, Pcg32& random) {
    const std::string& f = e.name;
    if (f == "rand") return random.uniform(a[0], a[1]);
    if (f == "min") return std::min(a[0], a[1]);
    if (f == "max") return std::max(a[0], a[1]);
    if (f == "floor") return std::floor(a[0]);
    if (f == "ceil") return std::ceil(a[0]);
    if (f == "round") return std::round(a[0]);
    if (f == "abs") return std::abs(a[0]);
    if (f == "sqrt") return std::sqrt(a[0]);
    if (f == "sin") return std::sin(degrees(a[0]));
    if (f == "cos") return std::cos(degrees(a[0]));
    return std::tan(degrees(a[0]));
}

double binary(const std::string& op, double a, double b) {
    if (op == "+") return a + b;
    if (op == "-") return a - b;
    if (op == "*") return a * b;
    if (op == "/") return a / b;
    if (op == "%") return std::fmod(a, b);
    if (op == "<") return a < b;
    if (op == ">") return a > b;
    if (op == "<=") return a <= b;
    if (op == ">=") return a >= b;
    if (op == "==") return a == b;
    return a != b;  // "!="
}

double evaluate_unchecked(const Expression& e, const VariableLookup& lookup, Pcg32& random,
                          const std::string& file) {
    switch (e.kind) {
    case Expression::Kind::number: return e.value;
    case Expression::Kind::variable: {
        double value = 0;
        if (!lookup(e.name, value)) throw_grammar_error(file, e.place, "unknown variable '" + e.name + "'");
        return value;
    }
    case Expression::Kind::unary: {
        double a = evaluate_unchecked(e.operands[0], lookup, random, file);
        return e.name == "!" ? double(a == 0) : -a;
    }
    case Expression::Kind::binary: {
        double a = evaluate_unchecked(e.operands[0], lookup, random, file);
        // && and || look at their right side only when it matters.
        if (e.name == "&&") return a != 0 && evaluate_unchecked(e.operands[1], lookup, random, file) != 0;
        if (e.name == "||") return a != 0 || evaluate_unchecked(e.operands[1], lookup, random, file) != 0;
        return binary(e.name, a, evaluate_unchecked(e.operands[1], lookup, random, file));
    }
    case Expression::Kind::call: {
        std::vector<double> arguments;
        for (const Expression& operand : e.operands)
            arguments.push_back(evaluate_unchecked(operand, lookup, random, file));
        return call(e, arguments, random);
    }
    }
    return 0;
}

}  // namespace

double evaluate(const Expression& expression, const VariableLookup& lookup, Pcg32& random,
                const std::string& file) {
    double value = evaluate_unchecked(expression, lookup, random, file);
    if (!std::isfinite(value))
        throw_grammar_error(file, expression.place, "the expression's value is not a finite number");
    return value;
}

int function_arity(const std::string& name) {
    for (const Function& f : functions)
        if (name == f.name) return f.arity;
    return -1;
}

}  // namespace boxlod
