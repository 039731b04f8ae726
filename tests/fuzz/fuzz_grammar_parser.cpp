// Grammars (data_gen/grammar_parser.h) and, when they parse, their derivation
// (data_gen/interpreter.h) under small limits so that each input runs quickly.
#include "data_gen/grammar_parser.h"
#include "data_gen/interpreter.h"
#include "fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return boxlod::fuzz::expect_only_input_errors([&] {
        boxlod::Grammar grammar =
            boxlod::parse_grammar(boxlod::fuzz::text(data, size), "fuzz.grammar", "/nonexistent");
        boxlod::BuildingOptions options;
        options.limits.max_depth = 20;
        options.limits.max_nodes = 2000;
        boxlod::generate_building(grammar, options);
    });
}
