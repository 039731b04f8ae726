// The sample grammars in data_gen/grammars/, compiled into the library:
// office (a tower), house (gable roof), classical (columns, cornices) and
// manual (the scale of the Cga-LoD manual's example model).
#pragma once
#include "data_gen/grammar.h"

#include <string>
#include <string_view>
#include <vector>

namespace boxlod {

struct SampleGrammar {
    std::string_view name;  // the file's stem
    std::string_view text;
};

// Every sample, sorted by name (generated at build time).
const std::vector<SampleGrammar>& sample_grammars();

std::string sample_names();  // "classical, house, manual, office"

// The parsed sample; its messages name it "NAME.grammar". An unknown name is
// an InputError listing the samples.
Grammar sample_grammar(const std::string& name);

}  // namespace boxlod
