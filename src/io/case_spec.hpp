#pragma once
// A case (a deck) as a typed value for the builders that start from a base
// deck and change it (sim/cup_case.cpp, chapter v1's v1_cup.cpp): one reader
// (from_toml) and one writer (to_toml).  A builder reads the base deck into a
// CaseSpec, sets fields (the mesh counts, the numerics, a tool's surfaces,
// speed or mass, the steps' durations, the friction, the material, the
// reduction), and writes the deck with to_toml; no builder names a key.
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
// The writer prints with toml++ (keys sorted; floats to 17 digits; integers as
// integers), so a deck written from a spec is the same bytes whatever path
// built it: the reuse key of a run is the hash of this text (sim/deck_job.hpp).
// Numbers the spec types as floats are written as floats.  Layout that is not
// meaning: a tool's speed and the reduction are written as [tool.speed] and
// [output.reduce] sections unless they were read inline; a contact's friction
// is written inline; the material's sub-tables are inline except those named
// in CaseSpec::material_sections.
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
  bool operator==(const CaseSpec& o) const {
    return mesh == o.mesh && material == o.material && numerics == o.numerics && tools == o.tools &&
           contacts == o.contacts && steps == o.steps && reduce == o.reduce && output == o.output && rest == o.rest;
  }
  /// The tool named `name`; throws InputError naming `where` when there is none.
  ToolSpec& tool(const std::string& name, const std::string& where);
};

/// Reads a deck's table; `where` (the file) names it in messages.  Throws
/// InputError (where: key: ...) when a piece has the wrong shape.
CaseSpec from_toml(const toml::table& root, const std::string& where);
/// read_toml_file + from_toml.
CaseSpec read_case(const std::string& path);

/// The deck as a toml++ table (the writer's structure) and as text.
toml::table to_toml_table(const CaseSpec& c);
std::string to_toml(const CaseSpec& c);

}  // namespace drawbend::io
