#include "base/freed_memory.h"

#include <malloc.h>

namespace boxlod {

bool keep_freed_memory() {
    // mallopt(3): setting either threshold also stops both from moving.
    constexpr int mapped_from = 32 << 20, trimmed_past = 256 << 20;
    const bool mapped = mallopt(M_MMAP_THRESHOLD, mapped_from) == 1;
    const bool trimmed = mallopt(M_TRIM_THRESHOLD, trimmed_past) == 1;
    return mapped && trimmed;
}

}  // namespace boxlod
