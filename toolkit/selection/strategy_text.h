// LoD selection strategies as text (the CLI's --strategy, CSV columns, reports):
//   distance:40,80,160        DistanceBands, ascending metres
//   pixels:200000,50000,1e4   PixelCount, descending pixels
//   ratio:0.2,0.05,0.01       ScreenRatio, descending fractions of the screen
//   diagonal[:MIN,MAX[,linear|square|square-root]]   BoxDiagonal (default 16,512,linear)
//   texel[:BUDGET]            TexelExact, optionally under an image-error budget
//   measured[:ERROR]          MeasuredSwitch, within ERROR of the original (default 0.05)
// format_strategy writes the text that parses back to the same strategy.
#pragma once
#include "toolkit/selection/lod_selection.h"

#include <string>

namespace boxlod {

// Throws InputError "where: what is wrong" for unknown names, malformed or
// badly ordered thresholds (validate_strategy's rules).
Strategy parse_strategy(const std::string& text, const std::string& where);

std::string strategy_name(const Strategy& strategy);    // distance, pixels, ratio, diagonal, texel, measured
std::string format_strategy(const Strategy& strategy);  // the full text, numbers exact

}  // namespace boxlod
