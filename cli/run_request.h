// `tierlift run`'s flags as given, and the request they make (pass::RunRequest): every flag
// but --const, which is read once the listings' constant tables are known (cmd_run.cpp).
#pragma once

#include <array>
#include <string>
#include <vector>

#include "front_end.h"
#include "tierlift/ir/ps1x_range.h"
#include "tierlift/ir/result.h"
#include "tierlift/pass/setup.h"

namespace tierlift::cli {

struct RunFlags {
  std::string vs, ps, size = "256x256", format = "rgba32f", filter = "point", address = "wrap";
  std::string pixel_center = "d3d9", front_face = "cw", output;
  std::vector<std::string> consts, inputs, attrs, textures, probes, bumps;
  int subtexel_bits = 0;
  std::string ps1x_max{ir::kDefaultPs1xPreset};
  unsigned threads = 0;
  std::string backend = "cpu", gpu;
  bool keep_alpha = false; // PNG: the shader's alpha as stored, not opaque
  std::string trace;       // --trace X,Y (run_trace.h)
  FrontEndOptions fe;      // -D, -I, --profile, --strict, --skip-validation, --json
  // --output1..--output3: the images of oC1..oC3 (D3D9 MRT); empty: not asked for.
  std::array<std::string, 3> more_outputs;
  // Mip chains and the sampler's mip state (all samplers): --mips auto|N, --mip-filter
  // none|point|linear, --lod-bias F, --max-mip-level N.
  std::string mips = "1", mip_filter = "none";
  float lod_bias = 0.0f;
  int max_mip_level = 0;
  bool srgb_texture = false, srgb_write = false; // --srgb-texture, --srgb-write
  // The depth buffer (run_depth.h): --depth-func, --depth-write on|off, --depth-clear V,
  // --depth-in FILE.pfm, --depth-out FILE.pfm; empty: not given. Any of them draws with one.
  std::string depth_func, depth_write, depth_clear, depth_in, depth_out;
};

// The request, or the first flag in error (rule "usage", exit 2), in the order the flags are
// read: size, format, the settings, filter, address, pixel centre, front face, sub-texel
// bits, ps1x max, the render targets (--output1..3: one more target each, given in order),
// mips, mip filter, max mip level.
ir::Result<pass::RunRequest> build_request(const RunFlags& f);

} // namespace tierlift::cli
