// `tierlift test --generate N --profile P --seed S`: the generated cases, made on every core.
#include <optional>
#include <thread>

#include <fmt/format.h>

#include "tierlift/corpus/cases.h"
#include "tierlift/generate/generate.h"

namespace tierlift::corpus {

ir::Result<std::vector<Case>> generated_cases(const std::string& profile, uint64_t seed,
                                              size_t count, unsigned threads) {
  // The differential run binds 2D textures and one render target: generate for that.
  gen::GenerateOptions options;
  options.only_2d_samplers = true;
  options.extra_outputs = false;
  std::vector<Case> out(count);
  // Each case's failure, if any (index order decides which one is reported).
  std::vector<std::optional<ir::Failure>> failed(count);
  auto make = [&](size_t i) {
    ir::Result<std::string> text = gen::generate_listing(profile, seed, i, options);
    if (!text) {
      failed[i] = std::move(text).failure();
      return;
    }
    Case& c = out[i];
    c.generated = true;
    c.text = std::move(*text);
    c.gen_profile = profile;
    c.gen_seed = seed;
    c.gen_index = i;
    c.id = case_id(fmt::format("generated/{}/seed{}/{:05}", profile, seed, i), c.text);
  };
  if (count == 0) return out;
  make(0); // in this thread: a profile the generator refuses fails here, before any thread
  if (failed[0]) return std::move(*failed[0]);
  // Each program depends on (profile, seed, index) alone, so the cases are the same on any
  // number of threads. The coordinator makes them all before the first worker starts: on
  // one core, 1,000 programs were about a twentieth of a one-worker run.
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  threads = static_cast<unsigned>(std::min<size_t>(threads, count - 1));
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < threads; ++t)
    pool.emplace_back([&, t] {
      for (size_t i = 1 + t; i < count; i += threads) make(i);
    });
  for (std::thread& th : pool) th.join();
  for (std::optional<ir::Failure>& f : failed)
    if (f) return std::move(*f);
  return out;
}

} // namespace tierlift::corpus
