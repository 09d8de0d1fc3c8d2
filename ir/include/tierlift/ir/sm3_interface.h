// Shader model 3 links its stages by semantic: a vs_3_0 writes o# registers declared
// dcl_texcoord1 o3, a ps_3_0 reads v# registers declared dcl_color0 v5. The interpreter and
// the code generator run the 2.0 interface (oPos, oFog, oPts, oD0-1, oT0-7 out of the vertex
// stage; colours v0-1 and coordinates t0-7 into the pixel stage, matched by number), so
// before running a 3.0 program they rename each o#/v# to the 2.0 register of the same
// semantic. Pairs then link as Direct3D links them, by (usage, index): vs_3_0 with ps_3_0,
// vs_2_0 with ps_3_0 and vs_3_0 with ps_2_0 alike (docs/spirv-mapping.md). A semantic the
// 2.0 interface has no register for (normal0, tangent0, texcoord9, color2, ...) rides in a
// texture-coordinate slot the program leaves free: the extra semantics in (usage, index)
// order take t7, t6, ... skipping the program's own texcoordN (NUMERICS.md F6). fog0 is
// such a semantic in shader model 3 (a vector, unclamped); a vertex program before 3.0
// writes the scalar oFog, which feed_fog moves into the slot a ps_3_0 reads fog0 from.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "tierlift/ir/diagnostic.h"
#include "tierlift/ir/program.h"
#include "tierlift/ir/result.h"

namespace tierlift::ir {

// The 2.0 register of a declared semantic: position0 → oPos, psize0 → oPts, colorN (N < 2)
// → oD N / v N, texcoordN (N < 8) → oT N / t N. nullopt for any other semantic (fog0,
// normal, tangent, texcoord8, ...), which then rides in a free texcoord slot.
std::optional<std::pair<RegFile, uint32_t>> semantic_register(ShaderStage stage, DeclUsage usage,
                                                              uint8_t usage_index);

// Errors (rule "not-supported", at the declaration) for what the renaming cannot carry: a
// pixel program's position0/psize0 (vertex outputs only), an extra semantic with no
// free slot left, two declarations on one register. Adds nothing for a
// program of another profile. (v# read relatively runs through relative_input_links, o#
// written relatively through relative_output_links.)
void check_semantic_interface(const Program& program, std::string_view backend,
                              DiagnosticSink& sink);

// A vertex and a pixel program link only where each slot the pixel program reads carries
// the same semantic out of the vertex program (or nothing), and no semantic sits in a
// different slot there: both hold when the two carry the same extra semantics. Refuses
// ("not-supported") a pair whose extra semantics would land in different slots.
Status check_semantic_pair(const Program& vertex, const Program& pixel);

// The program with every vs_3_0 o# and ps_3_0 v# (declarations, destinations, sources)
// renamed to its semantic_register or, for an extra semantic, its texcoord slot. Programs of other
// profiles come back unchanged. Call only on a program check_semantic_interface accepts.
// A source read relatively (v[aL + n]) keeps its v# number: it indexes
// relative_input_links, not one register; a destination written relatively (o[aL + n])
// keeps its o# number likewise: it indexes relative_output_links.
Program link_by_semantic(const Program& program);

// A vs_3_0 or ps_3_0 may read its inputs relatively, v[aL + n] (NUMERICS.md F13). Renamed by
// semantic, consecutive v# need not land in consecutive registers, so such a read indexes
// the program's declared inputs by v# number: entry k is the register v_k is read from once
// linked (its link_by_semantic register in a ps_3_0, v_k itself in a vs_3_0), nullopt where
// the program declares no v_k. A read of an index outside the table or of an undeclared
// v_k gives (0, 0, 0, 0), the rule of an out-of-range relative c# read (Direct3D 9 leaves
// both undefined). Sized to the profile's v# count (vs_3_0 16, ps_3_0 10); empty for the
// other profiles. Takes the program before linking.
using RelativeLinks = std::vector<std::optional<std::pair<RegFile, uint32_t>>>;
RelativeLinks relative_input_links(const Program& program);

// A vs_3_0 may write its outputs relatively, o[aL + n] or o[a0.c + n] (NUMERICS.md F13), the
// mirror of relative_input_links: entry k is the 2.0 register o_k is renamed to by
// link_by_semantic, nullopt where the program declares no o_k. A write whose index falls
// outside the table or on an undeclared o_k writes nothing (Direct3D 9 leaves it
// undefined); otherwise the write mask, _sat and a predicate apply as to a plain write of
// that register. Sized to vs_3_0's 12 o#; empty for the other profiles. Takes the program
// before linking.
RelativeLinks relative_output_links(const Program& program);

// Whether some instruction writes an o# relatively (a destination on RegFile::Output with rel).
bool writes_outputs_relatively(const Program& program);

// Whether some instruction reads a v# relatively (a source on RegFile::Input with rel).
bool reads_inputs_relatively(const Program& program);

// Whether a program of this profile holds its colours in [0, 1] (NUMERICS.md rule 26, F6).
// Direct3D 9 clamps a colour only where a stage before shader model 3 holds it: a vs_1_x/2_x
// writes oD0/oD1 saturated and a ps_1_x/2_x reads v0/v1 saturated. A vs_3_0's o# are general
// outputs and a ps_3_0 colour input is a float register like a texture coordinate, so
// neither clamps: false for vs_3_0 and ps_3_0, true for every earlier profile. Both devices
// saturate a vertex program's colour outputs and a pixel program's colour inputs by this.
bool saturates_colors(Profile profile);

// Whether a vertex stage's colours are saturated as it writes them, in a pair: unless both
// stages are shader model 3. A vs_3_0 before a ps_1_x/2_x has its colours clamped at its
// output too (the ps_2_0 reads them clamped again), so that the interpolators see finite
// values in [0, 1] as in every pair before 3.0; a pass without a vertex or pixel program
// counts as a 2.0 stage there. Only a vs_3_0 → ps_3_0 pair interpolates colours unclamped.
bool saturates_vertex_colors(Profile vertex, Profile pixel);

// The texcoord slot a ps_3_0 reads fog0 from (where link_by_semantic puts it); nullopt when
// it declares no fog0 or is of another profile.
std::optional<uint32_t> fog_slot(const Program& pixel);

// Direct3D 9 pairs a vertex program before 3.0 with a ps_3_0 that reads fog0: the pixel
// program sees (oFog, 0, 0, 0). The vertex program comes back with its oFog writes moved to
// the pixel program's fog0 slot (saturated, as oFog leaves the stage; the other components
// stay 0, every register's start value). Any other pair comes back unchanged. Both devices
// run the vertex program through this before linking the pair.
Program feed_fog(const Program& vertex, const Program& pixel);

} // namespace tierlift::ir
