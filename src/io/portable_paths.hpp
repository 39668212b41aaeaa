#pragma once
// Portable inputs: every relative path is resolved against the file that
// names it, and a run folder carries the tables its deck reads.
//
// Input files named in a deck: [material] hardening, a friction table's
// `nodes` / `lines` (surface law) and `table` (Stribeck law).  The deck reader
// resolves a relative one against the deck's folder (io/deck_friction.cpp)
// and names the deck line when it cannot read it.
//
//  - friction_argument: a builder's --friction is either a TOML inline table
//    typed on the command line (its relative files are taken from the current
//    folder, where the user typed them) or the path of a TOML file with a
//    [friction] table, such as the loop's friction_model.toml (its relative
//    files are taken from that file's folder).  Either way the result is a
//    typed friction (io/case_spec.hpp) whose file paths are absolute, so the
//    deck written from it reads the same files wherever the deck is put.
//  - portable_deck: the deck a builder writes into a run folder names each
//    input file by its bare name and the file is copied beside it, so the
//    folder can be moved or zipped and rerun elsewhere (`drawbend run
//    FOLDER/deck.toml`).  The rewrite depends on the text only (the same deck
//    gives the same bytes on every machine and in every folder).
#include <cstdint>
#include <optional>
#include <string>

#include "io/case_spec.hpp"

namespace drawbend::io {

/// The --friction value as a friction with absolute file paths (see above); none for an empty one.
/// Throws InputError naming the file or the argument when it is neither.
std::optional<FrictionSpec> friction_argument(const std::string& text, const std::string& base_dir);

/// `text` with every absolute path of an existing input file replaced by its
/// file name; when `copy_to` is not empty, each such file is copied there
/// (unless an identical copy is there already).  Two different files of the
/// same name: the second keeps its absolute path.
std::string portable_deck(const std::string& text, const std::string& copy_to = "");

/// Whether `dir` holds a byte-identical copy of every input file that
/// portable_deck(text) names by its bare name: a run folder whose deck text
/// matches is reusable only if its tables are the ones the deck reads now
/// (an edited flow curve or friction table of the same name is a new case).
bool portable_inputs_current(const std::string& text, const std::string& dir);

/// A case's fingerprint for naming its run folder: the portable deck text and
/// the name and bytes of every table it copies (fnv1a64, in the deck's order).
/// The same case gives the same fingerprint wherever its tables lie (another
/// checkout, another output folder, a cluster's mount point), and an edited
/// table gives another.
std::uint64_t portable_fingerprint(const std::string& text);

}  // namespace drawbend::io
