// tierlift run --trace: the two columns of effects/pixel_trace.h made on the devices the run
// used, printed as text or as the JSON result's "trace".
#include "run_trace.h"

#include <bit>
#include <fmt/format.h>

#include "commands.h"
#include "run_flags.h"
#include "tierlift/effects/graph/pixel_trace.h"
#include "tierlift/effects/graph/vulkan_device.h"

namespace tierlift::cli {
namespace {

nlohmann::json cell_json(const std::optional<effects::TraceCell>& cell) {
  if (!cell || cell->runs == 0) return nullptr;
  return {cell->value[0], cell->value[1], cell->value[2], cell->value[3]};
}

// The exact bits, since JSON has no NaN or infinity and a decimal hides a payload.
nlohmann::json bits_json(const std::optional<effects::TraceCell>& cell) {
  if (!cell || cell->runs == 0) return nullptr;
  nlohmann::json bits = nlohmann::json::array();
  for (float v : cell->value) bits.push_back(fmt::format("0x{:08x}", std::bit_cast<uint32_t>(v)));
  return bits;
}

nlohmann::json row_json(const effects::TraceRow& r) {
  return {{"line", r.line},
          {"text", r.text},
          {"dest", r.dest},
          {"interpreter", cell_json(r.interpreter)},
          {"vulkan", cell_json(r.vulkan)},
          {"interpreter_bits", bits_json(r.interpreter)},
          {"vulkan_bits", bits_json(r.vulkan)},
          {"interpreter_runs", r.interpreter ? nlohmann::json(r.interpreter->runs) : nullptr},
          {"vulkan_runs", r.vulkan ? nlohmann::json(r.vulkan->runs) : nullptr},
          {"differs", r.differs}};
}

nlohmann::json table_json(const effects::PixelTraceTable& t) {
  nlohmann::json rows = nlohmann::json::array();
  for (const effects::TraceRow& r : t.rows) rows.push_back(row_json(r));
  nlohmann::json j = {{"x", t.x}, {"y", t.y}, {"rows", rows}};
  if (t.has_interpreter) j["interpreter_covered"] = t.interpreter_covered;
  if (t.has_vulkan) j["vulkan_covered"] = t.vulkan_covered;
  j["first_difference"] =
      t.first_difference ? row_json(t.rows[*t.first_difference]) : nlohmann::json(nullptr);
  return j;
}

} // namespace

ir::Result<std::optional<PixelTraceRequest>> trace_request(const std::string& flag, bool has_ps,
                                                           const pass::RunRequest& run, bool cpu,
                                                           bool vulkan, const std::string& gpu) {
  if (flag.empty()) return std::optional<PixelTraceRequest>();
  ir::Result<pass::ProbePoint> at = parse_probe(flag);
  if (!at || at->x >= run.width || at->y >= run.height)
    return ir::fail("--trace", "usage",
                    fmt::format("--trace '{}': expected X,Y inside the {}x{} image", flag,
                                run.width, run.height));
  if (!has_ps)
    return ir::fail("--trace", "usage",
                    "--trace follows a pixel listing's instructions: give --ps");
  return std::optional<PixelTraceRequest>(
      PixelTraceRequest{at->x, at->y, run.width, run.height, run.format, cpu, vulkan, gpu});
}

int print_pixel_trace(const pass::Pass& pass, const PixelTraceRequest& req, Report& report) {
  if (!pass.pixel_program) {
    report.error("usage", "--trace follows the pixel listing: give --ps");
    return kExitUsage;
  }
  std::optional<cpu::PixelTrace> interpreter;
  std::optional<vulkan::ShaderTrace> vk;
  if (req.interpreter) {
    ir::Result<cpu::PixelTrace> traced =
        cpu::trace_pixel(pass, req.width, req.height, req.x, req.y);
    if (!traced) {
      report.error("trace", "interpreter: " + traced.message());
      return kExitInvalid;
    }
    interpreter = std::move(traced).value();
  }
  if (req.vulkan) {
    const ir::Result<vulkan::Device*> found = effects::vulkan_device(req.gpu);
    if (!found) {
      report.error("device", found.message());
      return kExitUsage;
    }
    vulkan::Device* device = *found;
    ir::Result<vulkan::ShaderTrace> traced =
        effects::trace_on_vulkan(*device, pass, req.width, req.height, req.format, req.x, req.y);
    if (!traced) {
      report.error("trace", "vulkan: " + traced.message());
      return kExitInvalid;
    }
    vk = std::move(traced).value();
  }
  const effects::PixelTraceTable table =
      effects::make_trace_table(*pass.pixel_program, req.x, req.y,
                                interpreter ? &*interpreter : nullptr, vk ? &*vk : nullptr);
  if (report.json())
    report.result()["trace"] = table_json(table);
  else
    fmt::print("{}", effects::format_trace_table(table));
  return 0;
}

} // namespace tierlift::cli
