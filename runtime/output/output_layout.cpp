// The tables of a run's outputs, their matching and their markdown; see output_layout.hpp.
#include "output/output_layout.hpp"

#include <array>
#include <vector>

namespace isosid::run::outputs {
namespace {

constexpr unsigned kNullable = Null;
/// an adaptive body's coordinates change in number with its model: they stay in the phases' files
constexpr std::string_view kNotJoined = "but for an adaptive body in an adaptive run's own file";
constexpr std::string_view kImpact = "an impact phase";

// ---------------------------------------------------------------- results.h5
// n: the output samples (`/time`); nq: the body's coordinates; nm: its modes that carry mass.
constexpr std::array kResults{
    Item{"/time", Float64, "n", "s", "", "the output samples' times: every output_interval, the run's start and end, and where the run stopped"},
    Item{"/provenance", Group, "", "", "", "where the run came from ([diagnostics.md](diagnostics.md#provenance))"},
    Item{"/provenance/program_version", Text, "", "", "", "version of isosid-run"},
    Item{"/provenance/command_line", Text, "", "", "", "the command line, or the library call that ran the scene"},
    Item{"/provenance/started_utc", Text, "", "", "", "when the run started, ISO 8601 UTC"},
    Item{"/provenance/input_roles", Texts, "inputs", "", "", "each input's role: scene, model, sid"},
    Item{"/provenance/input_paths", Texts, "inputs", "", "", "each input's path as the run read it"},
    Item{"/provenance/input_sha256", Texts, "inputs", "", "", "each input's SHA-256 when it was read"},
    Item{"/provenance/scene_overrides", Texts, "overrides", "", "the scene was run with --set", "the KEY=VALUE settings over the scene file"},
    Item{"/bodies", Group, "", "", "", "one group per body"},
    Item{"/bodies/<body>", Group, "", "", "", "the body named in the scene"},
    Item{"/bodies/<body>/position", Float64, "n × 3", "m", "", "the body frame's origin in the world"},
    Item{"/bodies/<body>/quaternion", Float64, "n × 4", "1", "", "the body frame's orientation, w x y z"},
    Item{"/bodies/<body>/tait_bryan", Float64, "n × 3", "rad", "", "the orientation as Tait-Bryan angles (x, then y, then z)"},
    Item{"/bodies/<body>/velocity", Float64, "n × 3", "m/s", "", "the frame origin's velocity, world"},
    Item{"/bodies/<body>/angular_velocity", Float64, "n × 3", "rad/s", "", "the frame's angular velocity, world"},
    Item{"/bodies/<body>/q", Float64, "n × nq", "[q]", kNotJoined, "the elastic coordinates (modal amplitudes; quasistatic and massless-boundary ones as solved at each sample)"},
    Item{"/bodies/<body>/qdot", Float64, "n × nq", "[q]/s", kNotJoined, "their rates"},
    Item{"/bodies/<body>/modal_energy", Float64, "n × nm", "J", kNotJoined,
         "½(q̇ₖ² + ωₖ²qₖ²) per mode that carries mass; a massless-boundary body's once its boundary is free"},
    Item{"/contacts", Group, "", "", "the scene has penalty contacts", "one group per contact"},
    Item{"/contacts/<contact>", Group, "", "", "", "the contact named in the scene"},
    Item{"/contacts/<contact>/force", Float64, "n × 3", "N", "", "the contact force on the slave body, world"},
    Item{"/contacts/<contact>/active_points", Float64, "n", "1", "", "Gauss points carrying load"},
    Item{"/contacts/<contact>/max_penetration", Float64, "n", "m", "", "the deepest penetration of a point"},
    Item{"/contacts/<contact>/spectrum_frequency", Float64, "frequencies", "Hz", "",
         "frequencies of the force pulse's spectrum: 0 to the output interval's Nyquist frequency in steps of a quarter of 1/duration"},
    Item{"/contacts/<contact>/spectrum_amplitude", Float64, "frequencies", "N s", "",
         "|∫F(t) e^(−2πiνt) dt| of the force magnitude, exact for the piecewise-linear force through the samples; at 0 Hz the impulse"},
    Item{"/contacts/<contact>/impact_modes", Group, "", "", "the target is flexible and the first contact has ended",
         "the modal view of the impact (as summary.json's contacts[].impact_modes)"},
    Item{"/contacts/<contact>/impact_modes/target", Text, "", "", "", "the target body"},
    Item{"/contacts/<contact>/impact_modes/index", Integers, "modes", "", "", "the target's integrated modes, counted from 1"},
    Item{"/contacts/<contact>/impact_modes/frequency_hz", Float64, "modes", "Hz", "", "their frequencies"},
    Item{"/contacts/<contact>/impact_modes/energy_ratio", Float64, "modes", "1", "", "E_k / E_0"},
    Item{"/contacts/<contact>/impact_modes/restitution", Float64, "modes", "1", "", "r_k"},
    Item{"/contacts/<contact>/impact_modes/label", Texts, "modes", "", "", "1F, 2F, … for the bending modes in the impact direction, else empty"},
    Item{"/contacts/<contact>/impact_modes/start_s", Float64, "1", "s", "", "the impact's start"},
    Item{"/contacts/<contact>/impact_modes/end_s", Float64, "1", "s", "", "its end"},
    Item{"/contacts/<contact>/impact_modes/kinetic_energy", Float64, "1", "J", "", "E_0: the slave's kinetic energy of approach"},
    Item{"/contacts/<contact>/impact_modes/direction", Float64, "3", "1", "", "the approach direction, world"},
    Item{"/contacts/<contact>/impact_modes/approach_speed", Float64, "1", "m/s", "", "v(t_S) along the direction"},
    Item{"/contacts/<contact>/impact_modes/separation_velocity", Float64, "1", "m/s", "", "v(t_E) along the direction"},
    Item{"/contacts/<contact>/impact_modes/point", Float64, "3", "m", "", "P: the target's contact point nearest the force centroid at the peak"},
    Item{"/hertz_contacts", Group, "", "", "the scene has Hertz contacts", "one group per Hertz contact"},
    Item{"/hertz_contacts/<contact>", Group, "", "", "", "the contact named in the scene"},
    Item{"/hertz_contacts/<contact>/force", Float64, "n × 3", "N", "", "the force on the first body, world"},
    Item{"/hertz_contacts/<contact>/overlap", Float64, "n", "m", "", "the spheres' overlap (0 when apart)"},
    Item{"/joints", Group, "", "", "the scene has joints", "one group per joint"},
    Item{"/joints/<joint>", Group, "", "", "", "the joint named in the scene"},
    Item{"/joints/<joint>/force", Float64, "n × 3", "N", "", "the constraint force on the joint's first body, world"},
    Item{"/joints/<joint>/torque", Float64, "n × 3", "N m", "", "the constraint torque on it, world"},
    Item{"/joints/<joint>/position_error", Float64, "n", "m", "", "how far the joint's points are apart"},
    Item{"/joints/<joint>/angle_error", Float64, "n", "rad", "", "how far the joint's axes are apart"},
    Item{"/energy", Group, "", "", "", "the energy balance"},
    Item{"/energy/kinetic", Float64, "n", "J", "", "kinetic energy of all bodies"},
    Item{"/energy/elastic", Float64, "n", "J", "", "elastic energy of all bodies"},
    Item{"/energy/gravity", Float64, "n", "J", "", "potential energy of gravity"},
    Item{"/energy/penalty", Float64, "n", "J", "", "energy stored in the contacts' penalty layers and Hertz contacts"},
    Item{"/energy/dissipated", Float64, "n", "J", "", "energy taken out by damping and friction so far"},
    Item{"/energy/total", Float64, "n", "J", "", "their balance: kinetic + elastic + gravity + penalty + dissipated"},
    Item{"/monitors", Group, "", "", "the scene has monitors", "one dataset per monitor"},
    Item{"/monitors/<monitor>", Float64, "n × 3, or n × points", "m|m/s|Pa", "",
         "a point's position (m) or velocity (m/s), world; a stress line's von Mises stress at its points (Pa)"},
};

// ---------------------------------------------------------------- summary.json
constexpr std::array kSummary{
    Item{"scene", String, "", "", "", "the scene file, or the name of a scene given as text"},
    Item{"provenance", Object, "", "", "", "where the run came from ([diagnostics.md](diagnostics.md#provenance))"},
    Item{"provenance.program_version", String, "", "", "", "version of isosid-run"},
    Item{"provenance.command_line", String, "", "", "", "the command line, or the library call that ran the scene"},
    Item{"provenance.started_utc", String, "", "", "", "when the run started, ISO 8601 UTC"},
    Item{"provenance.inputs", Array, "", "", "", "the run's inputs"},
    Item{"provenance.inputs[].role", String, "", "", "", "scene, model or sid"},
    Item{"provenance.inputs[].path", String, "", "", "", "the path as the run read it"},
    Item{"provenance.inputs[].sha256", String, "", "", "", "its SHA-256 when it was read"},
    Item{"provenance.scene_overrides", Array, "", "", "", "the KEY=VALUE settings over the scene file (--set)"},
    Item{"status", String, "", "", "",
         "running while the run is under way, then completed, failed (exit 1) or interrupted (SIGINT, SIGTERM or SIGHUP: exit 130, 143 or 129)"},
    Item{"failure", String, "", "", "the run failed", "why, in one line"},
    Item{"wall_time_s", Number, "", "s", "", "the run's wall time"},
    Item{"cpu_time_s", Number, "", "s", "", "its CPU time"},
    Item{"warnings", Array, "", "", "", "the run's warnings, one line each ([diagnostics.md](diagnostics.md))"},
    Item{"expected_warnings", Array, "", "", "", "warnings of the kinds the scene's [output] expected_warnings names"},
    Item{"end_time_s", Number, "", "s", "", "where the run ended: simulation.end_time, or where it stopped"},
    Item{"steps", Integer, "", "", "", "accepted time steps"},
    Item{"rejected_steps", Integer, "", "", "", "steps the integrator rejected and retried"},
    Item{"restarted_steps", Integer, "", "", "",
         "steps retried from the last accepted one, a tenth smaller, because the quasistatic modes found no equilibrium"},
    Item{"rhs_evaluations", Integer, "", "", "", "right-hand sides evaluated"},
    Item{"newton_iterations", Integer, "", "", "", "the implicit integrator's and the quasistatic modes' Newton iterations"},
    Item{"jacobian_setups", Integer, "", "", "", "the implicit integrator's Jacobian set-ups"},
    Item{"time_per_step_s", Number, "", "s", "", "wall time per accepted step"},
    Item{"time_split_s", Object, "", "s", "", "wall time of the right-hand sides by part"},
    Item{"time_split_s.static_solve", Number, "", "s", "", "the quasistatic and massless coordinates' static solve"},
    Item{"time_split_s.contacts", Number, "", "s", "", "the contacts' detection and forces"},
    Item{"time_split_s.joints", Number, "", "s", "", "the joints"},
    Item{"time_split_s.floating_frame", Number, "", "s", "", "the floating-frame equations"},
    Item{"time_split_s.output", Number, "", "s", "", "recording the output samples"},
    Item{"step_time_s", Object, "", "s", "", "wall time of the accepted steps, output included, by whether a contact carried load at the step's end"},
    Item{"step_time_s.loaded", Number, "", "s", "", "the steps that ended with a contact loaded"},
    Item{"step_time_s.loaded_steps", Integer, "", "", "", "their count"},
    Item{"step_time_s.unloaded", Number, "", "s", "", "the others"},
    Item{"step_time_s.unloaded_steps", Integer, "", "", "", "their count"},
    Item{"rhs_cost", Object, "", "", "", "what the right-hand sides did (bench/cost_model.py sets them against the unavoidable work)"},
    Item{"rhs_cost.evaluations", Integer, "", "", "", "right-hand sides"},
    Item{"rhs_cost.repeated", Integer, "", "", "", "those at the state of the evaluation before, answered from it"},
    Item{"rhs_cost.quasistatic_passes", Integer, "", "", "a single run, not an adaptive one", "the static solves' passes over the contact points"},
    Item{"rhs_cost.kept_contact_loads", Integer, "", "", "a single run, not an adaptive one",
         "contact evaluations that loaded the static solve's points without another pass"},
    Item{"rhs_cost.mean_active_points", Number, "", "", "", "contact points carrying load, on average over the evaluations"},
    Item{"contacts", Array, "", "", "", "one entry per penalty contact, in the scene's order"},
    Item{"contacts[].name", String, "", "", "", "the contact's name"},
    Item{"contacts[].start_s", Number | kNullable, "", "s", "", "the first onset of load; null if it never closed"},
    Item{"contacts[].end_s", Number | kNullable, "", "s", "", "the last release; null if never closed or still closed at the end"},
    Item{"contacts[].duration_s", Number | kNullable, "", "s", "", "from the first onset to the last release"},
    Item{"contacts[].intervals", Integer, "", "", "", "how often it opened and closed (single points bounce at onset)"},
    Item{"contacts[].touches", Array, "", "", "", "per impact, the instant the exact surfaces first touch (located by the root finder)"},
    Item{"contacts[].touches[].time_s", Number, "", "s", "", "the instant"},
    Item{"contacts[].touches[].gap_m", Number, "", "m", "", "the surfaces' gap there (the root finder's tolerance)"},
    Item{"contacts[].touches[].slave_parameter", Array | kNullable, "", "", "", "the point's parameter on the slave's patch"},
    Item{"contacts[].touches[].target_parameter", Array | kNullable, "", "", "",
         "the point's parameter on a flexible target's patch; null for planes, spheres, cylinders and rigid bodies"},
    Item{"contacts[].touches[].point_m", Array, "", "m", "", "the point, world"},
    Item{"contacts[].penalty_n_m3", Number, "", "N/m³", "", "the penalty used"},
    Item{"contacts[].penalty_source", String, "", "", "", "where it came from: the scene, the default rule, a search"},
    Item{"contacts[].peak_force_n", Number, "", "N", "", "the largest force"},
    Item{"contacts[].points_at_peak", Integer, "", "", "", "Gauss points carrying load at the peak"},
    Item{"contacts[].formulation", String, "", "", "", "general or gap-space"},
    Item{"contacts[].law", String, "", "", "", "the normal contact law (contact/contact_law.cpp's table: penalty)"},
    Item{"contacts[].pairs", Integer, "", "", "gap space", "the most points a pairing made"},
    Item{"contacts[].pairings", Integer, "", "", "gap space", "pairings made (once per impact)"},
    Item{"contacts[].repairings", Integer, "", "", "gap space", "those made again because the points slid along the target"},
    Item{"contacts[].condensed_points", Integer, "", "", "gap space",
         "the most pairs condensed at once, those within the pairing's reach (the dense compliance is their square)"},
    Item{"contacts[].reach_widenings", Integer, "", "", "gap space", "times the reach doubled because a pair beyond it would have pressed"},
    Item{"contacts[].edge_reached_s", Number | kNullable, "", "s", "",
         "when load first reached the edge elements of the contact surface, where forces beyond are not modelled (a warning); null if never"},
    Item{"contacts[].interface_left_s", Number | kNullable, "", "s", "",
         "when load first reached points of a Craig–Bampton surface its interface does not cover (a warning); null if never"},
    Item{"contacts[].hertz_estimate", Object, "", "", "the bodies' curvatures give one", "what Hertz's theory expects, before the run"},
    Item{"contacts[].hertz_estimate.approach_speed_m_s", Number, "", "m/s", "", "the approach speed it is for"},
    Item{"contacts[].hertz_estimate.contact_radius_m", Number, "", "m", "point contact", "the contact radius a"},
    Item{"contacts[].hertz_estimate.contact_half_width_m", Number, "", "m", "line contact", "the contact half-width"},
    Item{"contacts[].hertz_estimate.peak_force_n", Number, "", "N", "", "the peak force"},
    Item{"contacts[].hertz_estimate.contact_time_s", Number | kNullable, "", "s", "", "the contact time; null for a line contact"},
    Item{"contacts[].hertz_estimate.contact_element_m", Number, "", "m", "", "the contact surfaces' element size there"},
    Item{"contacts[].hertz_estimate.elements_per_radius", Number, "", "", "", "elements across the contact radius"},
    Item{"contacts[].impact_modes", Object, "", "", "the target is flexible and the first contact has ended",
         "the modal view of the impact: E_k = ½(η̇ₖ² + ωₖ²ηₖ²) at the first step after release, E_0 the slave's kinetic energy of approach"},
    Item{"contacts[].impact_modes.target", String, "", "", "", "the target body"},
    Item{"contacts[].impact_modes.start_s", Number, "", "s", "", "t_S: the impact's start"},
    Item{"contacts[].impact_modes.end_s", Number, "", "s", "", "t_E: its end"},
    Item{"contacts[].impact_modes.kinetic_energy_j", Number, "", "J", "", "E_0"},
    Item{"contacts[].impact_modes.direction", Array, "", "1", "", "the approach direction, world"},
    Item{"contacts[].impact_modes.approach_speed_m_s", Number, "", "m/s", "", "v(t_S) along it"},
    Item{"contacts[].impact_modes.separation_velocity_m_s", Number, "", "m/s", "", "v(t_E) along it"},
    Item{"contacts[].impact_modes.point_m", Array, "", "m", "", "P: the target's contact point nearest the force centroid at the peak"},
    Item{"contacts[].impact_modes.energy_ratio_total", Number, "", "1", "", "Σ E_k / E_0"},
    Item{"contacts[].impact_modes.modes", Array, "", "", "", "per integrated mode of the target"},
    Item{"contacts[].impact_modes.modes[].index", Integer, "", "", "", "the mode, counted from 1"},
    Item{"contacts[].impact_modes.modes[].frequency_hz", Number, "", "Hz", "", "its frequency"},
    Item{"contacts[].impact_modes.modes[].label", String | kNullable, "", "", "",
         "1F, 2F, … for the bending modes in the impact direction (cross-sections translating along it with at least half their kinetic energy); else null"},
    Item{"contacts[].impact_modes.modes[].energy_ratio", Number, "", "1", "", "E_k / E_0"},
    Item{"contacts[].impact_modes.modes[].restitution", Number, "", "1", "",
         "r_k = −(v(t_E) − φ_k(P)η̇_k(t_E))/v(t_S), velocities along the direction"},
    Item{"contacts[].impulse_ns", Number | kNullable, "", "N s", "", "the force's integral over the contact"},
    Item{"contacts[].max_penetration_m", Number, "", "m", "", "the deepest penetration of a point"},
    Item{"contacts[].penetration_per_hertz_approach", Number | kNullable, "", "1", "", "that over the Hertz approach; null without an estimate"},
    Item{"contacts[].penalty_too_soft", Boolean, "", "", "", "deeper than half the Hertz approach (a warning): the penalty layer, not the bodies, sets the forces"},
    Item{"contacts[].closed_at_end", Boolean, "", "", "", "still closed at the end (a warning): its duration and the rebound are not final"},
    Item{"contacts[].never_closed", Boolean, "", "", "", "never closed (a warning)"},
    Item{"hertz_contacts", Array, "", "", "", "one entry per Hertz contact"},
    Item{"hertz_contacts[].name", String, "", "", "", "the contact's name"},
    Item{"hertz_contacts[].stiffness_n_m1_5", Number, "", "N/m^1.5", "", "Hertz's stiffness: F = k δ^1.5"},
    Item{"hertz_contacts[].peak_force_n", Number, "", "N", "", "the largest force over its impacts"},
    Item{"hertz_contacts[].impacts", Array, "", "", "", "one entry per impact"},
    Item{"hertz_contacts[].impacts[].start_s", Number, "", "s", "", "its start"},
    Item{"hertz_contacts[].impacts[].end_s", Number | kNullable, "", "s", "", "its end; null if still closed at the end"},
    Item{"hertz_contacts[].impacts[].duration_s", Number | kNullable, "", "s", "", "its duration"},
    Item{"hertz_contacts[].impacts[].peak_force_n", Number, "", "N", "", "its peak force"},
    Item{"hertz_contacts[].impacts[].peak_time_s", Number, "", "s", "", "when"},
    Item{"hertz_contacts[].impacts[].impulse_ns", Number, "", "N s", "", "its impulse"},
    Item{"joints", Array, "", "", "", "one entry per joint"},
    Item{"joints[].name", String, "", "", "", "the joint's name"},
    Item{"joints[].peak_force_n", Number, "", "N", "", "the largest constraint force"},
    Item{"joints[].peak_torque_n_m", Number, "", "N m", "", "the largest constraint torque"},
    Item{"joints[].max_position_error_m", Number, "", "m", "", "the largest distance of its points"},
    Item{"joints[].max_angle_error_rad", Number, "", "rad", "", "the largest angle between its axes"},
    Item{"joints[].final_force_n", Array, "", "N", "the run has samples", "the constraint force at the end, world"},
    Item{"bodies", Array, "", "", "", "one entry per body"},
    Item{"bodies[].name", String, "", "", "", "the body's name"},
    Item{"bodies[].nq", Integer, "", "", "", "its elastic coordinates"},
    Item{"bodies[].quasistatic_modes", Integer, "", "", "", "how many of them are quasistatic or massless"},
    Item{"bodies[].final_position", Array, "", "m", "", "the frame's origin at the end, world"},
    Item{"bodies[].final_velocity", Array, "", "m/s", "", "its velocity at the end"},
    Item{"bodies[].final_angular_velocity", Array, "", "rad/s", "", "the frame's angular velocity at the end"},
    Item{"bodies[].final_modal_energy_j", Array, "", "J", "a flexible body", "½(q̇ₖ² + ωₖ²qₖ²) per mode that carries mass, at the end"},
    Item{"energy", Object, "", "", "", "the energy balance, damping and friction included"},
    Item{"energy.initial_j", Number, "", "J", "", "the total at the start"},
    Item{"energy.final_j", Number, "", "J", "", "at the end"},
    Item{"energy.max_rel_error", Number, "", "1", "", "the balance's largest drift over the initial total"},
    Item{"energy.dissipated_j", Number, "", "J", "", "what damping and friction took out"},
    Item{"energy.error_per_energy_in_motion", Number, "", "1", "a single run, not an adaptive one",
         "the largest drift over the largest kinetic + elastic + penalty energy"},
    Item{"energy.error_too_large", Boolean, "", "", "a single run, not an adaptive one", "that above 5 % (a warning)"},
    Item{"monitors", Array, "", "", "", "one entry per monitor, point monitors first"},
    Item{"monitors[].name", String, "", "", "", "the monitor's name"},
    Item{"monitors[].quantity", String, "", "", "", "position, velocity or von_mises"},
    Item{"monitors[].final", Array, "", "m|m/s", "a point monitor with samples", "its value at the end, world"},
    Item{"monitors[].arrival_s", Number | kNullable, "", "s", "a point monitor", "when the velocity first leaves its initial value by 1 %; null if never"},
    Item{"monitors[].reversal_s", Number | kNullable, "", "s", "a point monitor", "when it changes sign; null if never"},
    Item{"monitors[].line", String, "", "", "a stress monitor", "the line the stresses are sampled on (the monitor's `stress`)"},
    Item{"monitors[].peak_von_mises_pa", Number, "", "Pa", "a stress monitor", "the largest von Mises stress on the line"},
    Item{"monitors[].peak_time_s", Number, "", "s", "a stress monitor", "when"},
    Item{"monitors[].peak_position_m", Array, "", "m", "a stress monitor", "where, in the body's reference configuration"},
    Item{"monitors[].peak_depth_m", Number, "", "m", "a stress monitor on a contact surface's normal", "its depth below the contact surface"},
    Item{"reference", Object, "", "", "", "the scene's [reference] values against the run's"},
    Item{"reference.<value>", Object, "", "", "", "one reference value (peak_force_n, contact_time_s, a rebound velocity, …)"},
    Item{"reference.<value>.reference", Number, "", "", "", "the reference"},
    Item{"reference.<value>.value", Number | kNullable, "", "", "", "the run's; null where the run has none (a contact never closed)"},
    Item{"reference.<value>.rel_error", Number | kNullable, "", "1", "", "(value − reference)/|reference|"},
    Item{"reference.<value>.abs_error", Number, "", "", "the reference is 0 and the run has a value", "value − reference"},
    Item{"reference.<value>.source", String, "", "", "[reference] source = \"hertz\" set the value", "hertz: the contact's Hertz estimate"},
    Item{"adaptive", Object, "", "", "an adaptive run", "the adaptive loop's log ([usage.md](usage.md#adaptive-runs))"},
    Item{"adaptive.cache", String, "", "", "", "the folder of the refined SIDs' cache"},
    Item{"adaptive.builds", Integer, "", "", "", "refined SIDs built by isosid-prep"},
    Item{"adaptive.cache_hits", Integer, "", "", "", "refined SIDs found in the cache"},
    Item{"adaptive.preprocessing_wall_s", Number, "", "s", "", "the wait for isosid-prep over all tries"},
    Item{"adaptive.refused_tries_cpu_s", Number, "", "s", "", "CPU of impact tries that were run again"},
    Item{"adaptive.penalty_probes_cpu_s", Number, "", "s", "", "CPU of the penalty search's probes"},
    Item{"adaptive.penalty_search", Boolean, "", "", "", "[adaptive] penalty_search"},
    Item{"adaptive.penalties_n_m3", Object, "", "", "", "each contact's learned penalty"},
    Item{"adaptive.penalties_n_m3.<contact>", Number, "", "N/m³", "the contact's penalty was searched", "the penalty its later impacts start from"},
    Item{"adaptive.penalty_searches", Array, "", "", "", "one entry per penalty search"},
    Item{"adaptive.penalty_searches[].contact", String, "", "", "", "the contact"},
    Item{"adaptive.penalty_searches[].touch_s", Number, "", "s", "", "the impact's touch"},
    Item{"adaptive.penalty_searches[].window_end_s", Number, "", "s", "", "the end of the probes' window (the impact's first contact steps)"},
    Item{"adaptive.penalty_searches[].probes", Array, "", "", "", "the accepted try, then one entry per probe, ten times stiffer each"},
    Item{"adaptive.penalty_searches[].probes[].penalty_n_m3", Number, "", "N/m³", "", "the penalty"},
    Item{"adaptive.penalty_searches[].probes[].force_n", Number, "", "N", "", "the peak force over the window"},
    Item{"adaptive.penalty_searches[].probes[].steps", Integer, "", "", "", "steps taken over the window"},
    Item{"adaptive.penalty_searches[].probes[].from", String, "", "", "the accepted try's entry", "the accepted try"},
    Item{"adaptive.penalty_searches[].probes[].cpu_time_s", Number, "", "s", "a probe", "the probe's CPU"},
    Item{"adaptive.penalty_searches[].probes[].error", String, "", "", "a probe", "the probe's error; empty if none"},
    Item{"adaptive.penalty_searches[].penalty_n_m3", Number, "", "N/m³", "", "the penalty kept"},
    Item{"adaptive.penalty_searches[].decision", String, "", "", "", "why"},
    Item{"adaptive.phases", Array, "", "", "", "one entry per phase and try, in order"},
    Item{"adaptive.phases[].kind", String, "", "", "", "coarse or impact"},
    Item{"adaptive.phases[].switch_energy_change", Number, "", "1", "", "the relative change of energy in the switch of models into the phase"},
    Item{"adaptive.phases[].folder", String, "", "", "", "the phase's folder (phases/NN-…)"},
    Item{"adaptive.phases[].start_s", Number, "", "s", "", "its start"},
    Item{"adaptive.phases[].end_s", Number, "", "s", "", "its end"},
    Item{"adaptive.phases[].status", String, "", "", "", "its run's status"},
    Item{"adaptive.phases[].steps", Integer, "", "", "", "its accepted steps"},
    Item{"adaptive.phases[].cpu_time_s", Number, "", "s", "", "its CPU"},
    Item{"adaptive.phases[].energy_start_j", Number, "", "J", "", "the total energy at its start"},
    Item{"adaptive.phases[].energy_end_j", Number, "", "J", "", "at its end"},
    Item{"adaptive.phases[].contact", String, "", "", kImpact, "the impact's contact"},
    Item{"adaptive.phases[].try", Integer | String, "", "", kImpact, "the try, counted from 1; penalty: the impact run again at the searched penalty"},
    Item{"adaptive.phases[].touch_s", Number, "", "s", "an impact's try", "the touch that started the impact"},
    Item{"adaptive.phases[].width_m", Number, "", "m", kImpact, "the refined region's width"},
    Item{"adaptive.phases[].estimated_width_m", Number, "", "m", "an impact's try", "the width the contact's Hertz estimate asks for"},
    Item{"adaptive.phases[].output_interval_s", Number, "", "s", "an impact's try", "the phase's output interval"},
    Item{"adaptive.phases[].refined", Array, "", "", "an impact's try", "the refined models asked of isosid-prep"},
    Item{"adaptive.phases[].refined[].body", String, "", "", "", "the body"},
    Item{"adaptive.phases[].refined[].surface", String, "", "", "", "the contact surface refined"},
    Item{"adaptive.phases[].refined[].at", Array, "", "", "", "the refinement's centre, the surface's parameters"},
    Item{"adaptive.phases[].refined[].sid", String, "", "", "", "the refined SID in the cache"},
    Item{"adaptive.phases[].refined[].cache_hit", Boolean, "", "", "", "found in the cache, not built"},
    Item{"adaptive.phases[].refined[].preprocessing_s", Number, "", "s", "", "isosid-prep's wall time for it (0 from the cache)"},
    Item{"adaptive.phases[].preparation_wall_s", Number, "", "s", "an impact's try", "the wait for the try's models"},
    Item{"adaptive.phases[].utilization", Number, "", "1", kImpact,
         "the farthest loaded Gauss point from the refined region's centre over half its width"},
    Item{"adaptive.phases[].penalty_n_m3", Number, "", "N/m³", kImpact, "the penalty the phase ran with"},
    Item{"adaptive.phases[].error", String, "", "", "the phase's impact met an error", "the error"},
    Item{"adaptive.phases[].decision", String, "", "", kImpact, "the width rule's decision"},
    Item{"adaptive.phases[].accepted", Boolean, "", "", kImpact, "whether the try was kept"},
    Item{"adaptive.phases[].next_width_m", Number, "", "m", "an impact's try", "the width the rule asks for next"},
    Item{"adaptive.phases[].penalty_lowered", Object, "", "", "an error in the impact lowered the penalty", "the impact went on at a lower penalty"},
    Item{"adaptive.phases[].penalty_lowered.error", String, "", "", "", "the error"},
    Item{"adaptive.phases[].penalty_lowered.to_n_m3", Number, "", "N/m³", "", "the lower penalty"},
    Item{"adaptive.phases[].continued", Integer, "", "", "the part after a lowered penalty", "the part of the impact, counted from 1"},
    Item{"results_h5_error", String, "", "", "results.h5 could not be written", "why; the run failed"},
};

bool matches(std::string_view pattern, std::string_view path) {
  // split both at '/' (results.h5) or '.' (summary.json); "<...>" matches one whole name
  std::size_t p = 0, q = 0;
  while (p < pattern.size() && q < path.size()) {
    if (pattern[p] == '<') {
      const std::size_t close = pattern.find('>', p);
      if (close == std::string_view::npos) return false;
      p = close + 1;
      while (q < path.size() && path[q] != '/' && path[q] != '.' && path[q] != '[') ++q;
      continue;
    }
    if (pattern[p] != path[q]) return false;
    ++p, ++q;
  }
  return p == pattern.size() && q == path.size();
}

std::string type_text(unsigned type) {
  static constexpr std::pair<unsigned, std::string_view> kNames[] = {
      {Group, "group"}, {Float64, "float64"}, {Integers, "int64"},  {Text, "string"},   {Texts, "strings"},   {Boolean, "boolean"},
      {Integer, "integer"}, {Number, "number"}, {String, "string"}, {Array, "array"}, {Object, "object"}, {Null, "null"}};
  std::string out;
  for (const auto& [bit, name] : kNames)
    if (type & bit) out += (out.empty() ? "" : " or ") + std::string(name);
  return out;
}

/// A table cell's text: '|' would end the cell
std::string cell(std::string_view text) {
  std::string out;
  for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

std::string table(std::span<const Item> items, bool h5) {
  std::string out = h5 ? "| path | type | shape | units | when | meaning |\n|---|---|---|---|---|---|\n"
                       : "| key | type | units | when | meaning |\n|---|---|---|---|---|\n";
  for (const Item& i : items) {
    std::string units(i.units);
    for (std::size_t at; (at = units.find('|')) != std::string::npos;) units.replace(at, 1, ", ");
    out += "| `" + std::string(i.path) + "` | " + type_text(i.type) + (h5 ? " | " + std::string(i.shape) : "") + " | " + units + " | " +
           (i.when.empty() ? "always" : cell(i.when)) + " | " + cell(i.meaning) + " |\n";
  }
  return out;
}

}  // namespace

std::span<const Item> results_items() { return kResults; }
std::span<const Item> summary_items() { return kSummary; }

const Item* find(std::span<const Item> items, std::string_view path) {
  for (const Item& i : items)
    if (matches(i.path, path)) return &i;
  return nullptr;
}

std::string markdown() {
  return "# Outputs of isosid-run\n\n"
         "<!-- generated by `isosid-run --describe-outputs` from runtime/output/output_layout.cpp; do not edit -->\n\n"
         "A run writes `results.h5` and `summary.json` into its results folder ([usage.md](usage.md#outputs)); an adaptive run also "
         "keeps each phase's pair under `phases/`, laid out the same. A name in angle brackets stands for any one name: a body's, "
         "a contact's, a joint's or a monitor's from the scene. \"always\" means in every run's file; an item inside a group or an "
         "entry is there whenever its group or entry is, unless its own condition says otherwise.\n\n"
         "## results.h5\n\n"
         "n is the number of output samples (the length of `/time`), nq a body's elastic coordinates, nm its modes that carry "
         "mass. Every float64 dataset has a `units` attribute as below (`[q]`: the coordinates' own units).\n\n" +
         table(kResults, true) +
         "\n## summary.json\n\n"
         "Keys are written as paths: `contacts[].peak_force_n` is the key `peak_force_n` of each entry of the array `contacts`. "
         "Arrays of numbers are vectors in the world frame unless said otherwise.\n\n" +
         table(kSummary, false);
}

}  // namespace isosid::run::outputs
