#include "data_gen/samples.h"

#include "base/input_error.h"
#include "data_gen/grammar_parser.h"

namespace boxlod {

std::string sample_names() {
    std::string names;
    for (const SampleGrammar& sample : sample_grammars())
        names += (names.empty() ? "" : ", ") + std::string(sample.name);
    return names;
}

Grammar sample_grammar(const std::string& name) {
    for (const SampleGrammar& sample : sample_grammars())
        if (sample.name == name) return parse_grammar(std::string(sample.text), name + ".grammar");
    throw InputError("unknown sample grammar '" + name + "' (samples: " + sample_names() + ")");
}

}  // namespace boxlod
