// The allocator's policy for memory a program frees. glibc gives a freed block
// above its mapping threshold back to the system, and trims a heap's free top
// above its trim threshold; the first follows the largest block freed up to
// 32 MB, the second stays twice it. boxlod makes and frees buffers of
// megabytes by the thousand (a chain's switch distances compare each level in
// 64 views, each a few planes of up to 384 x 384 doubles, docs/cost.md:
// Switching levels), so each new one was faulted in page by page again: more
// than half of `boxlod tiles`' time.
#pragma once

namespace boxlod {

// Keeps freed memory in the process for the next allocation: blocks below
// 32 MB (mallopt's largest mapping threshold on 64-bit) come from a heap, and
// a heap's free top goes back to the system only past 256 MB. False where the
// allocator takes no such settings (a sanitizer's). Call it first in a
// program's main; results do not depend on it, only time.
bool keep_freed_memory();

}  // namespace boxlod
