// One pixel followed on both devices (pixel_trace.h): the Vulkan column's draw, the table
// that puts the interpreter's record beside the instrumented module's, and its text.
#include "tierlift/effects/graph/pixel_trace.h"

#include <bit>
#include <cmath>
#include <fmt/format.h>
#include <map>

#include "tierlift/assembly/printer.h"
#include "tierlift/ir/registers.h"

namespace tierlift::effects {
namespace {

// Bit-for-bit equality, except that any two NaNs are equal: neither D3D9 nor Vulkan says
// which NaN an operation returns, and a payload is no instruction's doing.
bool same_bits(float a, float b) {
  if (std::isnan(a) && std::isnan(b)) return true;
  return std::bit_cast<uint32_t>(a) == std::bit_cast<uint32_t>(b);
}

bool cells_differ(const TraceCell& a, const TraceCell& b, uint8_t mask) {
  if (a.runs != b.runs) return true;
  if (a.runs == 0) return false;
  for (int c = 0; c < 4; ++c)
    if ((mask & (1u << c)) && !same_bits(a.value[c], b.value[c])) return true;
  return false;
}

std::string cell_text(const std::optional<TraceCell>& cell, bool bits) {
  if (!cell) return "-";
  if (cell->runs == 0) return "(not run)";
  std::string s = format_value(cell->value, bits);
  if (cell->runs > 1) s += fmt::format(" x{}", cell->runs);
  return s;
}

} // namespace

ir::Result<vulkan::ShaderTrace> trace_on_vulkan(vulkan::Device& device, const pass::Pass& pass,
                                                uint32_t width, uint32_t height, img::Format format,
                                                uint32_t x, uint32_t y) {
  vulkan::TextureSet set(device);
  vulkan::StageTextures stages{};
  std::map<const img::Image*, vulkan::TextureId> uploaded; // one texture per image
  for (uint32_t s = 0; s < pass::kMaxSamplers; ++s) {
    const std::shared_ptr<const img::Image>& image = pass.textures[s].image;
    if (!image) continue;
    auto it = uploaded.find(image.get());
    if (it == uploaded.end()) {
      ir::Result<vulkan::TextureId> id = set.create(image->width, image->height, image->format);
      if (!id) return std::move(id).failure();
      if (ir::Status up = set.upload(*id, *image); !up) return std::move(up).failure();
      it = uploaded.emplace(image.get(), *id).first;
    }
    stages[s] = it->second;
  }
  ir::Result<vulkan::TextureId> target = set.create(width, height, format);
  if (!target) return std::move(target).failure();
  return set.draw_traced(pass, stages, *target, x, y);
}

PixelTraceTable make_trace_table(const ir::Program& program, uint32_t x, uint32_t y,
                                 const cpu::PixelTrace* interpreter,
                                 const vulkan::ShaderTrace* vulkan) {
  PixelTraceTable t;
  t.x = x;
  t.y = y;
  t.has_interpreter = interpreter != nullptr;
  t.has_vulkan = vulkan != nullptr;
  t.interpreter_covered = interpreter && interpreter->covered;
  std::vector<bool> recorded(program.code.size(), false);
  if (vulkan) {
    for (uint32_t i : vulkan->points)
      if (i < recorded.size()) recorded[i] = true;
    for (uint32_t h : vulkan->hits) t.vulkan_covered = t.vulkan_covered || h > 0;
  }
  for (size_t i = 0; i < program.code.size(); ++i) {
    const ir::Instruction& ins = program.code[i];
    TraceRow row;
    row.index = static_cast<uint32_t>(i);
    row.line = ins.loc.line;
    row.text = assembly::print_instruction(ins, program.profile);
    if (ins.op == ir::Opcode::TexDepth || ins.op == ir::Opcode::TexM3x2Depth) {
      row.dest = "oDepth"; // what they write, on both devices
      row.mask = 0x1;
    } else if (ins.dst) {
      row.dest = ins.dst->file == ir::RegFile::Addr
                     ? std::string("a0")
                     : ir::register_name(ins.dst->file, ins.dst->index);
      row.mask = ins.dst->mask & 0xF;
    }
    if (interpreter && i < interpreter->trace.hits.size() && ins.dst) {
      TraceCell c;
      c.value = interpreter->trace.value[i];
      c.runs = interpreter->trace.hits[i];
      row.interpreter = c;
    } else if (interpreter && ins.dst) {
      row.interpreter = TraceCell{}; // not covered: nothing ran
    }
    if (vulkan && recorded[i] && i < vulkan->hits.size()) {
      TraceCell c;
      c.value = vulkan->value[i];
      c.runs = vulkan->hits[i];
      row.vulkan = c;
    }
    row.differs =
        row.interpreter && row.vulkan && cells_differ(*row.interpreter, *row.vulkan, row.mask);
    if (row.differs && !t.first_difference) t.first_difference = t.rows.size();
    t.rows.push_back(std::move(row));
  }
  return t;
}

std::string format_value(const std::array<float, 4>& v, bool bits) {
  std::string s = "(";
  for (int c = 0; c < 4; ++c) {
    if (c) s += ", ";
    s += fmt::format("{:.9g}", v[c]);
    if (bits) s += fmt::format(" 0x{:08x}", std::bit_cast<uint32_t>(v[c]));
  }
  return s + ")";
}

std::string format_trace_table(const PixelTraceTable& t) {
  std::string out = fmt::format("trace of pixel {},{}", t.x, t.y);
  out += t.has_interpreter && t.has_vulkan ? " (interpreter | vulkan):\n"
         : t.has_vulkan                    ? " (vulkan):\n"
                                           : " (interpreter):\n";
  for (const TraceRow& r : t.rows) {
    std::string cells;
    if (t.has_interpreter) cells += cell_text(r.interpreter, r.differs);
    if (t.has_interpreter && t.has_vulkan) cells += " | ";
    if (t.has_vulkan) cells += cell_text(r.vulkan, r.differs);
    const std::string where = r.line ? fmt::format("{:5}", r.line) : std::string("    -");
    const std::string dest = r.dest.empty() ? std::string() : r.dest + " = ";
    out += fmt::format("{}  {:<28} {}{}{}\n", where, r.text, dest, r.dest.empty() ? "" : cells,
                       r.differs ? "   <- differs" : "");
  }
  if (t.has_interpreter && !t.interpreter_covered)
    out += fmt::format("interpreter: no triangle covers pixel {},{}: nothing ran\n", t.x, t.y);
  if (t.has_vulkan && !t.vulkan_covered)
    out += fmt::format("vulkan: the pixel module recorded nothing at {},{} (no triangle covers "
                       "it, or no instruction writes a register)\n",
                       t.x, t.y);
  if (!(t.has_interpreter && t.has_vulkan)) return out;
  if (!t.first_difference) {
    size_t compared = 0;
    for (const TraceRow& r : t.rows) compared += r.interpreter && r.vulkan ? 1 : 0;
    return out +
           fmt::format("no difference: the {} recorded instructions agree bit for bit\n", compared);
  }
  const TraceRow& r = t.rows[*t.first_difference];
  const std::string where =
      r.line ? fmt::format("line {}", r.line) : fmt::format("instruction {}", r.index + 1);
  auto side = [&](const TraceCell& c) {
    if (c.runs == 0) return std::string("(not run)");
    std::string s = format_value(c.value, true);
    if (c.runs > 1) s += fmt::format(" after {} runs", c.runs);
    return s;
  };
  return out + fmt::format("first difference: {} `{}`: interpreter {} = {}, Vulkan {} = {}\n",
                           where, r.text, r.dest, side(*r.interpreter), r.dest, side(*r.vulkan));
}

} // namespace tierlift::effects
