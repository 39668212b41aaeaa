#pragma once
// A case (a deck) as a typed value: one reader (from_toml) and one writer
// (to_toml).  Every builder returns one: the draw-bend, block and strip-draw
// builders (sim/drawbend_case, block_case, strip_draw_case) fill a spec from
// their physical parameters; the cup builder (sim/cup_case.cpp) and chapter
// v1 (v1_cup.cpp) read a base deck into a spec and set fields (the mesh
// counts, the numerics, a tool's surfaces, speed or mass, the steps'
// durations, the friction, the material, the reduction).  The deck commands'
// --threads sets NumericsSpec::threads.  The deck is written with to_toml; no
// builder concatenates deck text.
//
// Typed are the pieces the builders set or read: [mesh] (the quarter disk's
// sizes and counts), [numerics], [material] (io::MaterialSpec), every [[tool]]
// with its [[tool.surface]]s, every [[contact]] with its friction's law,
// nodes table and mu, every [[step]]'s name, duration and damping, and
// [output.reduce].  Every other key (the case's name, [sheet], the steps'
// fixed sets and tool drives, the output history, a tool's force given as a
// history, ...) is carried as read in the piece's `rest` table, so every deck
// reads, writes and reads back to the same spec (tests/unit/test_case_spec.cpp
// on every tracked deck).  The reader checks the shape only (a tool without a
// name, a surface that is not a table); the deck reader (io/deck.cpp), which
// every written deck goes through before it runs, checks the values.
//
// The writer prints with toml++ (keys sorted; strings in single quotes unless
// they need escapes; integers as integers) and then writes each float in the
// shortest form that reads back to the same double (0.8, not toml++'s
// 0.80000000000000004), always with a '.' or an exponent, so a deck written
// from a spec is the same bytes whatever path built it: the reuse key of a run is the hash of this text (sim/deck_job.hpp).
// Numbers the spec types as floats are written as floats.  Layout that is not
// meaning: a tool's speed and the reduction are written as [tool.speed] and
// [output.reduce] sections unless they were read inline; a contact's friction
// is written inline; the material's sub-tables are inline except those named
// in CaseSpec::material_sections.
//
// Comments: toml++ keeps none, so a deck's explanation is its header.  A
// builder puts a few lines in CaseSpec::comment (what the case is, its units,
// how to rerun it, and what a reader of a section must know, such as why a
// guard only warns); to_toml prints them first as "# " lines.  The longer
// explanations of the options live in the deck commands' --help.  The reader
// leaves the comment empty and the comparison ignores it (layout, not meaning).
#include <array>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <toml++/toml.h>

#include "io/material_spec.hpp"

namespace drawbend::io {

using Vec3Spec = std::array<double, 3>;

/// [mesh]: the quarter disk's sizes and counts (fe/disk.hpp); other kinds' keys stay in `rest`.
struct MeshSpec {
  std::optional<double> radius, thickness, core_fraction, polar_radius;  ///< [mm], [mm], -, [mm]
  std::optional<int64_t> core, ring, through;                             ///< element counts
  toml::table rest;                                                       ///< kind and every other key
  bool operator==(const MeshSpec&) const = default;
};

/// [numerics].
struct NumericsSpec {
  std::optional<double> dt_safety, target_dt;  ///< -, [s]
  std::optional<int64_t> threads;              ///< OpenMP threads of `drawbend run`
  toml::table rest;                            ///< mass_scaling, hourglass, ...
  bool operator==(const NumericsSpec&) const = default;
};

/// A history { t = [s, ...], v = [...] } (a tool's speed).
struct HistorySpec {
  std::vector<double> t, v;
  bool written_inline = false;  ///< layout only (read inline); not compared
  bool operator==(const HistorySpec& o) const { return t == o.t && v == o.v; }
};

/// One [[tool.surface]] (contact/surface.hpp): every key the deck reader knows.
struct SurfaceSpec {
  std::string kind;  ///< "plane", "cylinder" or "torus"
  std::optional<Vec3Spec> origin, normal, axis;
  std::optional<double> radius, tube_radius, r_min, r_max, z_min, z_max, angle_min, angle_max;  ///< [mm], [rad]
  std::optional<bool> inside;
  toml::table rest;  ///< keys the deck reader does not know (it reports them)
  bool operator==(const SurfaceSpec&) const = default;
};

/// One [[tool]].
struct ToolSpec {
  std::string name;
  std::optional<std::string> drive;       ///< "fixed", "velocity" or "force"
  std::optional<Vec3Spec> direction;
  std::optional<HistorySpec> speed;       ///< [mm/s]; a constant speed stays in `rest`
  std::optional<double> force, mass, stop;  ///< [N], [t], [mm]; a force history stays in `rest`
  std::vector<SurfaceSpec> surfaces;
  toml::table rest;
  bool operator==(const ToolSpec&) const = default;
  /// The first surface of `kind`, or nullptr.
  SurfaceSpec* surface(const std::string& kind);
};

/// A contact's friction = { law, nodes, mu, ... } (written inline).
struct FrictionSpec {
  std::optional<std::string> law;
  std::optional<std::string> nodes;  ///< Table 6.1-format CSV (law "surface")
  std::optional<double> mu;          ///< law "coulomb"
  toml::table rest;                  ///< interval, lines, table, ...
  bool operator==(const FrictionSpec&) const = default;
};

/// One [[contact]].
struct ContactSpec {
  std::optional<FrictionSpec> friction;  ///< none: frictionless
  toml::table rest;                      ///< faces, tool, ...
  bool operator==(const ContactSpec&) const = default;
};

/// One [[step]].
struct StepSpec {
  std::string name;
  std::optional<double> duration, damping;  ///< [s], [1/s]
  toml::table rest;                         ///< fixed, tool_drive, ...
  bool operator==(const StepSpec&) const = default;
};

/// [output.reduce] (io/case_reduction.hpp).
struct ReduceSpec {
  std::string kind, tool, step;
  std::optional<std::string> holder;
  std::optional<double> stroke, ramp;  ///< [mm]
  std::optional<int64_t> every;        ///< cycles
  bool written_inline = false;         ///< layout only; not compared
  bool operator==(const ReduceSpec& o) const {
    return kind == o.kind && tool == o.tool && step == o.step && holder == o.holder && stroke == o.stroke &&
           ramp == o.ramp && every == o.every;
  }
};

struct CaseSpec {
  std::optional<MeshSpec> mesh;
  std::optional<MaterialSpec> material;
  std::optional<NumericsSpec> numerics;
  std::vector<ToolSpec> tools;
  std::vector<ContactSpec> contacts;
  std::vector<StepSpec> steps;
  std::optional<ReduceSpec> reduce;
  toml::table output;  ///< [output] but reduce (history_interval, history, ...); empty: no [output]
  toml::table rest;    ///< every other top-level section ([case], [sheet], [guards], ...) as read
  /// Keys of [material] sub-tables written as [material.KEY] sections rather than inline (layout only).
  std::set<std::string> material_sections;
  /// The deck's header comment, one entry a line, printed as "# line" (layout only; see above).
  std::vector<std::string> comment;
  bool operator==(const CaseSpec& o) const {
    return mesh == o.mesh && material == o.material && numerics == o.numerics && tools == o.tools &&
           contacts == o.contacts && steps == o.steps && reduce == o.reduce && output == o.output && rest == o.rest;
  }
  /// The tool named `name`; throws InputError naming `where` when there is none.
  ToolSpec& tool(const std::string& name, const std::string& where);
};

/// `n` OpenMP threads for `drawbend run` of the deck (the deck commands' --threads):
/// numerics.threads = n (a [numerics] made if there is none); nothing for n = 0.
void set_threads(CaseSpec& c, int64_t n);

/// A contact's friction table { law, nodes, mu, ... } as a FrictionSpec (the shape only, as from_toml).
FrictionSpec read_friction(toml::table t);
/// The laws a builder sets (io/deck_friction.hpp; the deck reader checks the values):
/// { law = "coulomb", mu }, { law = "stribeck", table, interval }, { law = "surface", nodes, interval }.
FrictionSpec coulomb_friction(double mu);
FrictionSpec stribeck_friction(const std::string& table, int64_t interval);
FrictionSpec surface_friction(const std::string& nodes, int64_t interval);
/// The friction as one line of inline TOML in a fixed order: the law, then its input file
/// (nodes, lines, table), then its other keys by name, e.g. { law = "coulomb", mu = 0.1 } or
/// { law = "stribeck", table = "t.csv", interval = 100 } (a run's description; the deck's
/// [[contact]] friction itself is written by to_toml).
std::string friction_text(const FrictionSpec& f);

/// Reads a deck's table; `where` (the file) names it in messages.  Throws
/// InputError (where: key: ...) when a piece has the wrong shape.
CaseSpec from_toml(const toml::table& root, const std::string& where);
/// read_toml_file + from_toml.
CaseSpec read_case(const std::string& path);

/// The deck as a toml++ table (the writer's structure) and as text.
toml::table to_toml_table(const CaseSpec& c);
std::string to_toml(const CaseSpec& c);

}  // namespace drawbend::io
