// Feedback, the stiff case: the glow of frame n blended into frame n + 1 with gain g,
//   x_{n+1} = s + g·x_n,
// modelled as a three-pass graph over 1×1 textures run frame after frame on each device
// (the dx9 blur listings, one tap of non-zero weight each):
//   decay   tmp ← g·acc          (Replace)
//   carry   acc ← tmp            (Replace; a pass cannot read its own target)
//   source  acc += src           (ONE/ONE; src holds s, the frame's glow)
// Closed forms: for g < 1 the steady state is s/(1 − g) and, with the source off, the value
// falls to 1/e of it in ceil(−1/ln g) ≈ 1/(1 − g) frames; g = 1 grows by s a frame, g > 1
// geometrically. In RGBA8 each store rounds to k/255, so the rise stops short where
// round(g·k + s·255) = k and the decay stalls at the largest k with round(g·k) = k,
// k* = ceil(0.5/(1 − g)) − 1 (ties aside). The expected values are the store rule's
// recurrence x' = Q(Q(g·x) + s) in fp32 (what the passes compute), the ideal the closed form.
#include <cmath>
#include <limits>

#include <fmt/format.h>

#include "stress_common.h"
#include "tierlift/effects/glow/builtin_listing.h"

namespace tierlift::effects::stress {
namespace {

using img::Format;

constexpr double kSource = 2.0 / 255; // s: a whole RGBA8 step count, so RGBA8 stores it exactly

unsigned rise_frames(double g) {
  return g < 1 ? unsigned(std::ceil(12 / (1 - g))) : 200;
}

struct FeedbackGraph {
  EffectGraph graph;
  std::string error;
};

FeedbackGraph feedback_graph(Format f, double g) {
  FeedbackGraph out;
  ListingResult vs = builtin_listing("gpugems21/listing1_blur8_coords.vsh");
  if (!vs) {
    out.error = vs.message();
    return out;
  }
  ListingResult ps = builtin_listing("gpugems21/listing2_blur8_weighted_sum.psh");
  if (!ps) {
    out.error = ps.message();
    return out;
  }
  EffectGraph& gr = out.graph;
  for (const char* name : {"src", "acc", "tmp"})
    gr.textures.push_back({name, 1, 1, f, name == std::string("src")});
  auto pass = [&](std::string name, std::string from, std::string to, double weight,
                  pass::BlendMode blend) {
    PassDesc d = listing_pass(std::move(name), *vs, *ps, to);
    const float w = float(weight);
    for (unsigned k = 0; k < kTapsPerBlurPassDx9; ++k) {
      d.draw.vs_constants.f.push_back({0.5f, 0.5f, 0, 0}); // the one texel's centre
      d.draw.ps_constants.f.push_back(k == 0 ? pass::Vec4{w, w, w, w} : pass::Vec4{0, 0, 0, 0});
    }
    pass::SamplerState s;
    s.filter = pass::Filter::Point;
    s.address_u = s.address_v = pass::AddressMode::Clamp;
    bind_reads(d, 0, from, s, 1, false);
    d.draw.blend = blend;
    gr.passes.push_back(std::move(d));
  };
  pass("decay", "acc", "tmp", g, pass::BlendMode::Replace);
  pass("carry", "tmp", "acc", 1, pass::BlendMode::Replace);
  pass("source", "src", "acc", 1, pass::BlendMode::OneOne);
  out.error = check_graph(gr).message();
  return out;
}

// One frame of the recurrence in fp32, each store by the format's rule.
double step(Format f, double g, double x, bool source) {
  const double decayed = device_store(f, float(g) * float(x));
  return source ? device_store(f, float(decayed) + float(device_store(f, kSource))) : decayed;
}

struct WayFeedback {
  std::string way, error;
  double steady = 0, before = 0; // after rise_frames and one frame earlier
  double efold_frames = -1;      // frames to fall to 1/e with the source off (-1: never)
  double stall = 0;              // where the decay stopped moving (RGBA8)
};

WayFeedback run_way(PassDevice& device, const EffectGraph& graph, Format f, double g) {
  WayFeedback out;
  out.way = device.name();
  img::Image src(1, 1, f);
  for (float& c : src.rgba) c = float(device_store(f, kSource));
  ImageMap inputs{{"src", src}};
  auto fail = [&](std::string e) {
    out.error = std::move(e);
    return out;
  };
  if (ir::Status begun = device.begin_run(graph, inputs); !begun) return fail(begun.message());
  auto frame = [&](bool source) -> std::string {
    for (size_t i = 0; i < (source ? 3u : 2u); ++i)
      if (auto drawn = device.draw(graph.passes[i]); !drawn) return drawn.message();
    return device.finish().message();
  };
  auto read = [&](double& v) -> std::string {
    ir::Result<img::Image> im = device.read_texture("acc");
    if (!im) return im.message();
    v = im->rgba.at(0);
    return {};
  };
  const unsigned n = rise_frames(g);
  for (unsigned i = 0; i < n; ++i) {
    if (std::string e = frame(true); !e.empty()) return fail(e);
    if (i + 2 == n)
      if (std::string e = read(out.before); !e.empty()) return fail(e);
  }
  if (std::string e = read(out.steady); !e.empty()) return fail(e);
  if (g >= 1 || !std::isfinite(out.steady)) return out;
  // The source off: count frames down to 1/e, and keep going (RGBA8) until it stops moving.
  const double target = out.steady / std::exp(1.0);
  const unsigned cap = unsigned(std::ceil(8 / (1 - g)));
  double x = out.steady;
  for (unsigned i = 1; i <= cap; ++i) {
    if (std::string e = frame(false); !e.empty()) return fail(e);
    double next = 0;
    if (std::string e = read(next); !e.empty()) return fail(e);
    if (out.efold_frames < 0 && next <= target) out.efold_frames = i;
    const bool stalled = next == x;
    x = next;
    if (out.efold_frames >= 0 && (f != Format::RGBA8 || stalled)) break;
  }
  out.stall = x;
  return out;
}

std::vector<StressRow> feedback(const StressOptions& o, Format f, double g) {
  const std::string fname(img::format_name(f));
  const FeedbackGraph fg = feedback_graph(f, g);
  std::vector<WayFeedback> ways;
  std::string error = fg.error;
  for (const std::string& way : o.ways) {
    if (!error.empty()) break;
    std::unique_ptr<PassDevice> d = o.make_device ? o.make_device(way) : nullptr;
    if (!d) continue;
    ways.push_back(run_way(*d, fg.graph, f, g));
    if (!ways.back().error.empty()) error = fmt::format("{}: {}", way, ways.back().error);
  }
  if (ways.empty() && error.empty()) error = "no way could run (no device)";

  // The recurrence: the expected values.
  const unsigned n = rise_frames(g);
  double x = 0, before = 0;
  for (unsigned i = 0; i < n; ++i) before = x, x = step(f, g, x, true);
  const double steady = x;
  const double s = device_store(f, kSource);
  const double ideal = g < 1 ? s / (1 - g) : g == 1 ? n * s : s * (std::pow(g, n) - 1) / (g - 1);
  const double rel = f == Format::RGBA8     ? 0
                     : f == Format::RGBA16F ? 4 * std::ldexp(1.0, -10)
                                            : 1e-5;
  const bool stable = g < 1 && std::isfinite(steady) && steady == before;

  std::vector<StressRow> rows;
  StressRow ss;
  ss.id = fmt::format("feedback.g{:g}.{}.steady", g, fname);
  ss.regime = "feedback";
  ss.format = fname;
  ss.quantity = g < 1 ? fmt::format("value after {} frames (steady state)", n)
                      : fmt::format("value after {} frames (no steady state)", n);
  ss.expected = steady;
  ss.tolerance = f == Format::RGBA8 ? 1.0 / 255 : rel * std::fabs(steady);
  ss.has_ideal = true;
  ss.ideal = ideal;
  ss.bound = g < 1    ? "recurrence x' = Q(Q(g·x) + s); ideal s/(1−g)"
             : g == 1 ? "recurrence; ideal n·s (grows without bound)"
                      : "recurrence; ideal s·(g^n − 1)/(g − 1) (geometric growth)";
  ss.note = stable ? "stable" : g < 1 ? "not settled" : "unstable";
  if (f == Format::RGBA8 && g < 1)
    ss.note += fmt::format(": rise stops at {}/255, ideal {:.4g}/255", std::lround(steady * 255),
                           ideal * 255);
  if (f == Format::RGBA8 && g >= 1 && steady >= 1) ss.note += ": saturates at 1";
  ss.error = error;
  for (const WayFeedback& w : ways)
    if (w.error.empty()) ss.measured.push_back({w.way, w.steady, {}});
  rows.push_back(ss);
  if (g >= 1) return rows;

  // The decay from the recurrence's steady state.
  double e_frames = -1, y = steady, stall = steady;
  const unsigned cap = unsigned(std::ceil(8 / (1 - g)));
  for (unsigned i = 1; i <= cap; ++i) {
    const double next = step(f, g, y, false);
    if (e_frames < 0 && next <= steady / std::exp(1.0)) e_frames = i;
    const bool stalled = next == y;
    y = next;
    if (e_frames >= 0 && (f != Format::RGBA8 || stalled)) break;
  }
  stall = y;
  StressRow dr;
  dr.id = fmt::format("feedback.g{:g}.{}.decay", g, fname);
  dr.regime = "feedback";
  dr.format = fname;
  dr.quantity = "frames to fall to 1/e, source off (-1: never)";
  dr.expected = e_frames;
  // The expected count is the store rule's own recurrence in double; a device computes
  // g·y + s in fp32 first, which can move one frame's store across a rounding boundary (the
  // 0.99·50 = 49.5 tie is one) and so shift the 1/e crossing by at most that one frame.
  dr.tolerance = 1;
  dr.has_ideal = true;
  dr.ideal = std::ceil(-1 / std::log(g));
  dr.bound = "recurrence; ideal ceil(−1/ln g) ≈ 1/(1−g)";
  dr.error = error;
  for (const WayFeedback& w : ways)
    if (w.error.empty()) dr.measured.push_back({w.way, w.efold_frames, {}});
  rows.push_back(dr);
  if (f == Format::RGBA8) {
    StressRow st;
    st.id = fmt::format("feedback.g{:g}.rgba8.stall", g);
    st.regime = "feedback";
    st.format = fname;
    st.quantity = "where the decay stalls (×255)";
    st.expected = std::round(stall * 255);
    // Same recurrence, same reason: one store on the other side of a tie moves the level
    // where g·y rounds back to y by one step.
    st.tolerance = 1;
    st.has_ideal = true;
    // The largest k with k − g·k < ½ (1e-9: 0.5/(1 − 0.9) is 5 plus a rounding error).
    st.ideal = std::ceil(0.5 / (1 - g) - 1e-9) - 1;
    st.bound = "largest k with round(g·k) = k: ceil(0.5/(1−g)) − 1 (ties aside)";
    // What the devices did (the recurrence's tie may go the other way: ± 1 step).
    const double seen = ways.empty() ? st.expected : std::round(ways.front().stall * 255);
    st.note = seen > 0 ? fmt::format("never decays below {}/255", seen) : "decays to 0";
    st.error = error;
    for (const WayFeedback& w : ways)
      if (w.error.empty()) st.measured.push_back({w.way, std::round(w.stall * 255), {}});
    rows.push_back(st);
  }
  return rows;
}

} // namespace

std::vector<StressCase> feedback_cases() {
  std::vector<StressCase> out;
  for (Format f : {Format::RGBA8, Format::RGBA16F, Format::RGBA32F})
    for (double g : {0.5, 0.9, 0.99, 1.0, 1.01})
      out.push_back({fmt::format("feedback.g{:g}.{}", g, img::format_name(f)),
                     [f, g](const StressOptions& o) { return feedback(o, f, g); }});
  return out;
}

} // namespace tierlift::effects::stress
