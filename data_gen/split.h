// How a split divides a scope's extent along one axis (CGA's subdivision
// split): absolute sizes are kept, 'relative ones are a fraction of the
// extent, ~floating ones share what is left in proportion to their nominal
// size, and one group of entries may repeat as often as it fits.
#pragma once
#include "data_gen/grammar.h"

#include <cstddef>
#include <vector>

namespace boxlod {

struct SplitSlot {
    Size::Kind kind = Size::Kind::absolute;
    double value = 0;       // metres, fraction or nominal metres
    bool repeated = false;  // part of the repeat group (the group's slots are contiguous)
};

struct SplitPiece {
    std::size_t slot = 0;  // which slot made this piece
    double offset = 0, size = 0;
};

struct SplitLayout {
    std::vector<SplitPiece> pieces;
    bool fits = true;   // false: the absolute and relative sizes alone exceed the extent
    double needed = 0;  // metres the fixed sizes need
};

// Lays out `slots` over `extent`. The repeat group is repeated
// round(room / nominal length) times (at least once) when it holds a
// floating size, floor(room / length) times otherwise, and never more than
// `max_pieces` pieces are made. Without floating sizes the space left over
// stays empty.
SplitLayout layout_split(const std::vector<SplitSlot>& slots, double extent, std::size_t max_pieces);

}  // namespace boxlod
