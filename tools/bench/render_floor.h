#pragma once
// The render benchmark's floor (polarcade-bench render --floor): the AVX2 kernel taken apart into
// kernels that do only some of its work over the same spans, so the table shows what each part
// costs: nothing (the rest of the frame), the stores alone, the fetches and stores (no blend), the
// blend alone (no fetch), and the whole kernel. x86-64 with AVX2 only.
#include <vector>

#include "render/sprite_span.h"

namespace polar::bench {

// The parts, cheapest first, the last being the kernel drawSprite uses (avx2); empty without AVX2.
std::vector<render::detail::NamedKernel> floorKernels();

}  // namespace polar::bench
