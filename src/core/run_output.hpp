#pragma once
// What a run leaves on disk, as one typed contract: the history (history.csv,
// its columns named by the Signal enum), the contact map (one CSV per contact
// pair and snapshot) and the pin maps the loop reads.  The column
// names, the file names and the comment keys live here and nowhere else:
// io/run_case writes maps with write_contact_map, sim/drawbend_case reads the
// last one with read_contact_map, Chapter 4 exports pin maps with
// pin_map_header, and loop/maps reads them back.  Units: mm, MPa, N, mm/s.
#include <string>
#include <vector>

namespace drawbend::run_output {

/// history.csv: one row per output interval.
inline constexpr const char* kHistoryFile = "history.csv";

/// The columns of history.csv.  Every run (io/run_case) writes `time` to
/// `balance_error`, in this order, then the deck's [output] history signals
/// under the names the deck gives them.  The draw-bend builder
/// (sim/drawbend_case) names its deck signals from the second group, so its
/// readers (sim/, the chapters) use the enum, not a spelled string.
enum class Signal {
  // Every run, in file order.
  time,           ///< time_s [s]
  step,           ///< step: the step's name (text)
  dt,             ///< dt_s: stable time step [s]
  kinetic,        ///< kinetic_mJ [mJ = N mm]
  internal,       ///< internal_mJ
  hourglass,      ///< hourglass_mJ
  external_work,  ///< external_work_mJ
  friction,       ///< friction_mJ
  damping,        ///< damping_mJ
  balance_error,  ///< balance_error: relative energy-balance error [-]
  // The draw-bend case's deck signals.
  outlet_force,            ///< outlet_force_N: reaction at the outlet grip, z [N, half model]
  back_tension,            ///< back_tension_N: applied force at the inlet end, x [N, half model]
  inlet_x,                 ///< inlet_x_mm: inlet end displacement, x [mm]
  pin_force_x,             ///< pin_force_x_N: force on the pin, x [N]
  pin_force_z,             ///< pin_force_z_N: force on the pin, z [N]
  strain_inside,           ///< strain_inside: axial strain at the contact-side spot [-]
  plastic_strain_inside,   ///< plastic_strain_inside: equivalent plastic strain there [-]
  strain_outside,          ///< strain_outside: axial strain at the free-side spot [-]
  plastic_strain_outside,  ///< plastic_strain_outside: equivalent plastic strain there [-]
  outlet_force_full,       ///< F_Y_full_strip_N: -2 x outlet_force_N, the full strip's outlet tension [N]
  back_tension_full,       ///< F_X_full_strip_N: -2 x back_tension_N, the full strip's back tension [N]
};
/// The column name of a signal (with its unit suffix): Signal::outlet_force -> "outlet_force_N".
const char* signal_name(Signal s);
/// The columns every history.csv starts with (Signal::time .. Signal::balance_error), in order.
std::vector<std::string> run_history_columns();
/// eps_mid_<k>: the draw-bend case's outside-surface axial strain of mid-wrap section k [-].
std::string mid_wrap_strain(int k);

/// One slave node of a contact map.
struct ContactMapRow {
  int node = -1;
  double x = 0, y = 0, z = 0;     ///< current position [mm]
  double x0 = 0, y0 = 0, z0 = 0;  ///< reference position [mm]
  int surface = -1;               ///< tool surface in contact (-1: none)
  double u_tool = 0;              ///< angle about the surface axis [deg] (cylinder, torus) or in-plane [mm] (plane)
  double v_tool = 0;              ///< along the axis [mm] (cylinder, torus) or second in-plane coordinate (plane)
  double pressure = 0;            ///< [MPa]
  double area = 0;                ///< tributary area [mm^2]
  double normal_force = 0;        ///< [N]
  double tangential_force = 0;    ///< [N]
  double slip_speed = 0;          ///< [mm/s]
  double penetration = 0;         ///< [mm]
};

struct ContactMap {
  std::vector<std::string> comments;  ///< without the leading '#'
  std::vector<ContactMapRow> rows;
  std::string path;                   ///< where it was read from
};

/// The columns of a contact map, in file order.
const std::vector<std::string>& contact_map_columns();
/// contact_<snapshot>_<pair>.csv
std::string contact_map_name(int snapshot, int pair);
/// Write atomically (core/csv.hpp), with `comments` above the header.
void write_contact_map(const std::string& path, const std::vector<std::string>& comments,
                       const std::vector<ContactMapRow>& rows);
/// Read a contact map (or a pin map, which is one with more comments); throws InputError (file:line: column).
ContactMap read_contact_map(const std::string& path);
/// Only the pressure and area columns (all a pressure map needs; other columns may be absent).
struct PressureColumns {
  std::vector<std::string> comments;
  std::vector<double> pressure, area;  ///< [MPa], [mm^2], one per row
  std::vector<int> line;               ///< file line of each row
};
PressureColumns read_pressure_columns(const std::string& path);
/// The contact map of `pair` with the highest snapshot number in `dir`; throws InputError when there is none.
std::string last_contact_map(const std::string& dir, int pair);

/// Pin maps for the loop (`drawbend loop --maps DIR`): pin_<d>mm.csv, a contact
/// map whose comments state the full-strip back tension it was computed at.
inline constexpr const char* kReferenceBackTension = "reference_back_tension_N:";
inline constexpr const char* kBendingForce = "bending_force_N:";
std::string pin_map_name(const std::string& diameter_text);  ///< pin_<d>mm.csv
/// The first comment line of an exported pin map (full-strip back tension, and what the map is).
std::string pin_map_header(double reference_back_tension_N, const std::string& what);

}  // namespace drawbend::run_output
