#include "ch5_steps.hpp"
namespace ch5 {
void diluted_new_method(Chapter&, const Inputs&, const FeMaps&) {}
void undiluted_new_method(Chapter&, const Inputs&, const FeMaps&) {}
void map_sensitivity(Chapter&, const Inputs&, const FeMaps&, const FeOptions&) {}
}
