// Selection strategies as typed on the command line (toolkit/selection/strategy_text.h).
#include "fuzz_target.h"
#include "toolkit/selection/strategy_text.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    return boxlod::fuzz::expect_only_input_errors([&] {
        boxlod::Strategy strategy = boxlod::parse_strategy(boxlod::fuzz::text(data, size), "--strategy");
        boxlod::format_strategy(strategy);
    });
}
