// Arithmetic in grammars: numbers, variables (rule parameters, attributes,
// scope.sx/sy/sz), + - * / %, comparisons, && || !, and a few functions,
// rand(low, high) among them.
#pragma once
#include "base/random.h"
#include "data_gen/grammar.h"

#include <functional>
#include <string>

namespace boxlod {

// Finds a variable's value; false if there is no such variable.
using VariableLookup = std::function<bool(const std::string& name, double& value)>;

// Throws InputError "file:line:column: ..." for an unknown variable or a
// result that is not a finite number. rand() draws from `random`.
double evaluate(const Expression& expression, const VariableLookup& lookup, Pcg32& random,
                const std::string& file);

// How many arguments a built-in function takes; -1 if there is no such function.
int function_arity(const std::string& name);

}  // namespace boxlod
