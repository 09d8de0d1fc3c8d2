// The frames of a moving scene on every device (scene_animation.h), and the files of the
// first device's frames.
#include "scene_animation.h"

#include <algorithm>

#include <fmt/format.h>

#include "tierlift/image/compare.h"
#include "tierlift/image/io.h"

namespace tierlift::effects {
namespace {

constexpr unsigned kStripFrames = 8;  // frames in the contact strip, evenly spaced
constexpr uint32_t kStripWidth = 240; // each frame's width in the strip (or less)

img::Image opaque(const img::Image& im) {
  img::Image o = im;
  for (size_t i = 3; i < o.rgba.size(); i += 4) o.rgba[i] = 1.0f;
  return o;
}

// Frames side by side, each shrunk by a whole factor to at most kStripWidth wide (box
// average), 2-pixel gaps of grey between them.
img::Image contact_strip(const std::vector<const img::Image*>& frames) {
  const img::Image& f0 = *frames.front();
  const uint32_t n = std::max<uint32_t>(1, (f0.width + kStripWidth - 1) / kStripWidth);
  const uint32_t w = std::max<uint32_t>(1, f0.width / n), h = std::max<uint32_t>(1, f0.height / n);
  constexpr uint32_t kGap = 2;
  const auto count = static_cast<uint32_t>(frames.size());
  img::Image strip(count * w + (count - 1) * kGap, h, img::Format::RGBA32F);
  for (size_t i = 0; i < strip.rgba.size(); ++i) strip.rgba[i] = i % 4 == 3 ? 1.0f : 0.5f;
  for (uint32_t k = 0; k < count; ++k)
    for (uint32_t y = 0; y < h; ++y)
      for (uint32_t x = 0; x < w; ++x) {
        float* d = strip.at(k * (w + kGap) + x, y);
        for (int c = 0; c < 3; ++c) {
          double sum = 0;
          for (uint32_t j = 0; j < n; ++j)
            for (uint32_t i = 0; i < n; ++i)
              sum += std::clamp(frames[k]->at(std::min(f0.width - 1, x * n + i),
                                              std::min(f0.height - 1, y * n + j))[c],
                                0.0f, 1.0f);
          d[c] = static_cast<float>(sum / (n * n));
        }
        d[3] = 1.0f;
      }
  return strip;
}

std::string write_frames(io::OutputFolder& out, const std::vector<img::Image>& frames) {
  std::vector<std::string> names;
  for (size_t f = 0; f < frames.size(); ++f) names.push_back(fmt::format("frame-{:04}.png", f + 1));
  names.push_back("frames-strip.png");
  std::vector<std::string> paths;
  for (const std::string& n : names) { // every name checked before the first is written
    ir::Result<std::string> path = out.path(n);
    if (!path) return path.message();
    paths.push_back(*path);
  }
  for (size_t f = 0; f < frames.size(); ++f)
    if (ir::Status s = img::write_png(paths[f], opaque(frames[f])); !s) return s.message();
  std::vector<const img::Image*> picked;
  const size_t count = std::min<size_t>(kStripFrames, frames.size());
  for (size_t k = 0; k < count; ++k)
    picked.push_back(&frames[count == 1 ? 0 : k * (frames.size() - 1) / (count - 1)]);
  if (ir::Status s = img::write_png(paths.back(), contact_strip(picked)); !s) return s.message();
  return {};
}

} // namespace

bool Animation::all_within() const {
  return std::all_of(pairs.begin(), pairs.end(),
                     [](const FramePairAgreement& p) { return p.frames_within == p.frames; });
}

std::string run_animation(const EffectPlan& plan, const img::Image& scene,
                          const std::vector<std::string>& devices, const DeviceMaker& make,
                          unsigned frames, io::OutputFolder* folder, const SceneAt& scene_at,
                          const std::function<FrameProgress(const std::string&)>& progress,
                          Animation& out) {
  const std::string final_name(kFinalTexture);
  const img::Format format = plan.graph.find_texture(final_name)->format;
  // Every device's frames are kept until the last device has been compared with them
  // (frames × devices images of the final's size).
  std::vector<std::vector<img::Image>> kept;
  for (size_t d = 0; d < devices.size(); ++d) {
    std::unique_ptr<PassDevice> device = make(devices[d]);
    if (!device) return fmt::format("{}: no device", devices[d]);
    std::vector<img::Image> mine;
    for (size_t e = 0; e < d; ++e)
      out.pairs.push_back({devices[e], devices[d], frames, 0, 0, 1, 0, {}});
    const size_t first_pair = out.pairs.size() - d;
    auto sink = [&](unsigned f, const ImageMap& images) -> ir::Status {
      const img::Image& now = images.find(final_name)->second;
      for (size_t e = 0; e < d; ++e) {
        ir::Result<img::Comparison> c = img::compare(kept[e][f], now);
        if (!c) return std::move(c).failure();
        const img::Verdict v = img::judge(*c, format);
        FramePairAgreement& p = out.pairs[first_pair + e];
        p.frames_within += v.pass ? 1 : 0;
        if (!v.pass && p.first_failure.empty())
          p.first_failure = fmt::format("frame {}: {}", f + 1, v.summary);
        if (c->max_abs_all > p.worst_max_abs || f == 0) {
          p.worst_max_abs = std::max(p.worst_max_abs, c->max_abs_all);
          p.worst_frame = f + 1;
        }
        p.worst_identical = std::min(p.worst_identical, c->identical_share);
      }
      mine.push_back(now);
      return ir::ok_status();
    };
    EffectFrames run = run_effect_frames(plan, scene, *device, frames, {final_name}, sink, scene_at,
                                         progress ? progress(devices[d]) : nullptr);
    if (!run.run.ok()) return run.run.message();
    out.times.push_back({devices[d], run.run.value()});
    kept.push_back(std::move(mine));
  }
  if (folder && !kept.empty()) return write_frames(*folder, kept.front());
  return {};
}

} // namespace tierlift::effects
