// The glow benchmarks' shared parts (glow_frames.h).
#include "glow_frames.h"

#include <map>

#include <fmt/format.h>

#include "tierlift/effects/scenes/default_scene.h"

namespace tierlift::bench {

effects::PlanResult glow_plan(effects::Tier tier, img::Format format, uint32_t width,
                              uint32_t height, unsigned taps) {
  effects::EffectParams p;
  p.tier = tier;
  p.width = width;
  p.height = height;
  p.downsample = 4;
  p.format = format;
  p.profile.max_taps = taps;
  p.subtexel_bits = 0; // as the tests and `tierlift glow` run it (exact bilinear weights)
  return effects::build_glow(p);
}

const img::Image& glow_scene(uint32_t width, uint32_t height) {
  static std::map<std::pair<uint32_t, uint32_t>, img::Image> scenes;
  auto [it, made] = scenes.try_emplace({width, height});
  if (made) it->second = effects::make_default_scene(width, height, img::Format::RGBA32F);
  return it->second;
}

bool run_device_frames(benchmark::State& state, effects::PassDevice& device,
                       const effects::PlanResult& plan, const img::Image& scene,
                       img::Image* final_frame) {
  auto fail = [&](const std::string& e) {
    state.SkipWithError(e.c_str());
    return false;
  };
  if (!plan) return fail(plan.message());
  img::Image input = scene;
  input.format = plan->graph.textures.front().format;
  img::quantize_in_place(input); // stored in the graph's format, as run_graph does
  const effects::ImageMap inputs{{std::string(effects::kSceneTexture), input}};
  if (ir::Status s = device.begin_run(plan->graph, inputs); !s) return fail(s.message());
  auto frame = [&] {
    for (const effects::PassDesc& p : plan->graph.passes)
      if (auto s = device.draw(p); !s) return fail(p.name + ": " + s.message());
    if (ir::Status s = device.finish(); !s) return fail(s.message());
    return true;
  };
  if (!frame()) return false; // warm-up, untimed: first touches, worker threads, pipelines
  for (auto _ : state)
    if (!frame()) return false;
  state.counters["passes"] = double(plan->graph.passes.size());
  state.counters["taps"] = double(plan->taps.size());
  state.counters["pixels"] = double(scene.width) * scene.height;
  if (final_frame) {
    ir::Result<img::Image> read = device.read_texture(std::string(effects::kFinalTexture));
    if (!read) return fail(read.message());
    *final_frame = std::move(*read);
  }
  return true;
}

vulkan::Device* bench_vulkan_device(std::string* error) {
  static const ir::Result<std::unique_ptr<vulkan::Device>> dev = vulkan::Device::create({});
  if (!dev) {
    *error = dev.message();
    return nullptr;
  }
  error->clear();
  return dev->get();
}

void register_glow_scaling(const std::string& name, DeviceFactory make, int iterations) {
  struct Size {
    uint32_t w, h;
  };
  for (Size s : {Size{480, 270}, Size{1920, 1080}, Size{3840, 2160}})
    for (unsigned taps : {7u, 13u}) {
      auto* b = benchmark::RegisterBenchmark(
          fmt::format("BM_GlowScale_{}/{}x{}/taps:{}", name, s.w, s.h, taps).c_str(),
          [make, s, taps](benchmark::State& state) {
            std::string error;
            std::unique_ptr<effects::PassDevice> device = make(&error);
            if (!device) {
              state.SkipWithError(error.c_str());
              return;
            }
            run_device_frames(state, *device,
                              glow_plan(effects::Tier::Dx9, img::Format::RGBA32F, s.w, s.h, taps),
                              glow_scene(s.w, s.h));
          });
      b->Unit(benchmark::kMillisecond)->UseRealTime();
      if (iterations > 0) b->Iterations(iterations);
    }
}

} // namespace tierlift::bench
