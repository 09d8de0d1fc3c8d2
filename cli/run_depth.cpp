// `tierlift run`'s depth buffer flags (run_depth.h).
#include "run_depth.h"

#include <charconv>
#include <cmath>

#include <fmt/format.h>

#include "run_files.h"
#include "tierlift/image/io.h"
#include "tierlift/pass/depth.h"

namespace tierlift::cli {
namespace {

ir::Failure usage_error(std::string message) {
  return ir::fail("run", "usage", std::move(message));
}

} // namespace

bool wants_depth(const RunFlags& f) {
  return !f.depth_func.empty() || !f.depth_write.empty() || !f.depth_clear.empty() ||
         !f.depth_in.empty() || !f.depth_out.empty();
}

ir::Result<pass::DepthStencilState> depth_state(const RunFlags& f) {
  pass::DepthStencilState ds;
  if (!wants_depth(f)) return ds;
  ds.depth_test = true;
  ds.depth_write = true;
  if (!f.depth_func.empty() && !pass::parse_compare_func(f.depth_func, ds.depth_func))
    return usage_error(fmt::format("--depth-func '{}': expected never, less, equal, lessequal, "
                                   "greater, notequal, greaterequal or always",
                                   f.depth_func));
  if (f.depth_write == "off")
    ds.depth_write = false;
  else if (!f.depth_write.empty() && f.depth_write != "on")
    return usage_error(fmt::format("--depth-write '{}': expected on or off", f.depth_write));
  if (!f.depth_clear.empty()) {
    float v = 0;
    const char* end = f.depth_clear.data() + f.depth_clear.size();
    auto [ptr, ec] = std::from_chars(f.depth_clear.data(), end, v);
    if (ec != std::errc() || ptr != end || !(v >= 0.0f && v <= 1.0f))
      return usage_error(
          fmt::format("--depth-clear '{}': expected a number in [0, 1]", f.depth_clear));
    if (!f.depth_in.empty())
      return usage_error("--depth-clear and --depth-in both set the starting depth: give one");
  }
  return ds;
}

ir::Result<effects::SinglePassDepth> depth_start(const RunFlags& f, uint32_t width,
                                                 uint32_t height) {
  effects::SinglePassDepth out;
  if (!f.depth_clear.empty()) out.clear = std::stof(f.depth_clear); // checked by depth_state
  if (f.depth_in.empty()) return out;
  if (!f.depth_in.ends_with(".pfm"))
    return usage_error(
        fmt::format("--depth-in {}: expected a .pfm image (floats, depth in red)", f.depth_in));
  img::ImageResult read = img::read_pfm(f.depth_in);
  if (!read) return ir::fail(f.depth_in, "io", read.message());
  const img::Image& im = *read;
  if (im.width != width || im.height != height)
    return usage_error(fmt::format("--depth-in {}: the image is {}x{}, the target {}x{}",
                                   f.depth_in, im.width, im.height, width, height));
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) {
      const float z = im.at(x, y)[0];
      if (!(z >= 0.0f && z <= 1.0f))
        return usage_error(fmt::format("--depth-in {}: pixel {},{} holds {}, outside the depth "
                                       "range [0, 1]",
                                       f.depth_in, x, y, z));
    }
  out.initial = std::make_shared<const img::Image>(std::move(read).value());
  return out;
}

std::string write_depth_output(const std::string& path, const img::Image& depth) {
  ir::Status written = img::write_pfm(path, depth, img::PfmChannels::Grey);
  return written ? std::string() : written.message();
}

std::string write_depth_outputs(const RunFlags& f, const effects::SinglePassRun& r) {
  if (f.depth_out.empty()) return {};
  const bool both = r.draws.size() == 2;
  for (size_t i = 0; i < r.draws.size(); ++i) {
    if (!r.draws[i].depth) continue;
    const std::string path = i == 0 ? f.depth_out : vulkan_output(f.depth_out);
    if (i > 0 && !both) break;
    if (std::string err = write_depth_output(path, *r.draws[i].depth); !err.empty())
      return path + ": " + err;
  }
  return {};
}

void print_depth_agreement(const effects::SinglePassRun& r) {
  if (!r.depth_agreement) return;
  const img::Comparison& c = *r.depth_agreement;
  fmt::print("depth: cpu vs vulkan: max abs {:.3g}, identical pixels {:.2f} %: {}\n", c.max_abs[0],
             c.identical_share * 100.0, r.depth_verdict->pass ? "bit for bit" : "NOT BIT FOR BIT");
}

nlohmann::json depth_json(const RunFlags& f, const pass::DepthStencilState& ds,
                          const effects::SinglePassRun& r) {
  if (!pass::uses_depth(ds)) return nullptr;
  nlohmann::json j = {
      {"func", std::string(pass::compare_func_name(ds.depth_func))},
      {"write", ds.depth_write},
      {"clear", f.depth_clear.empty() ? 1.0f : std::stof(f.depth_clear)},
      {"in", f.depth_in.empty() ? nlohmann::json() : nlohmann::json(f.depth_in)},
      {"out", f.depth_out.empty() ? nlohmann::json() : nlohmann::json(f.depth_out)}};
  if (r.depth_agreement)
    j["agreement"] = {{"max_abs", r.depth_agreement->max_abs[0]},
                      {"identical_share", r.depth_agreement->identical_share},
                      {"bit_identical", r.depth_verdict->pass},
                      {"summary", r.depth_verdict->summary}};
  return j;
}

} // namespace tierlift::cli
