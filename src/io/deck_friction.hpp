#pragma once
// A contact's friction law from its deck table (a deck's [[contact]]
// friction, a builder's --friction checked on its own): kept apart from
// deck.cpp so that a new law is added here only.  The material is read and
// built by io/material_spec.hpp, the one place that knows the [material] keys.
#include <memory>
#include <string>

#include <toml++/toml.h>

#include "friction/friction_law.hpp"
#include "io/deck_context.hpp"

namespace drawbend::io {

/// friction = { law = "coulomb", mu = 0.1 }, or
/// friction = { law = "stribeck", table = "table_3_1.csv" | mu_BL, mu_EHL, L_BL, L_EHL, Ra_um, eta_Pa_s,
///              interval = 100 }  (cycles over which the sliding speed is averaged, Sec. 3.3.2), or
/// friction = { law = "surface", nodes = "table_6_1.csv" | lines = "table_5_16.csv", interval = 100,
///              p_min = 0, p_max = 80, v_min = 6.35, v_max = 101.6 }  (the mu(p, v) law of Ch. 6;
///              v_min/v_max only with nodes: with lines they are the outer lines' speeds)
/// `w` names the table in messages ("contact.friction" in a deck; a builder's
/// --friction checked on its own names the option or its file's [friction]).
std::shared_ptr<friction::FrictionLaw> make_friction(const DeckContext& c, const toml::table& t,
                                                     const std::string& deck_dir,
                                                     const std::string& w = "contact.friction");

}  // namespace drawbend::io
