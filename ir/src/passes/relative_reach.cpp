// Analysis: which constants relative addressing can reach.
#include <algorithm>

#include "tierlift/ir/passes.h"

namespace tierlift::ir {

uint32_t relative_constant_limit(Profile p) {
  const uint32_t limit = limits(p).float_consts;
  return is_vertex(p) ? std::max<uint32_t>(limit, 256) : limit;
}

} // namespace tierlift::ir
