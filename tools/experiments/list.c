/* SPDX-License-Identifier: MIT */
#include "experiment.h"

const experiment experiment_list[] = {
    {"e1", "e1_twitch", "twitch: a one-frame activation pulse of the biceps (arm, 1 kg)", EXPERIMENT_MAX_PULSE_WIDTH,
     experiment_e1_twitch, false},
    {"e2", "e2_relaxation", "active and passive force while the activation falls from 1 to 0 in 3 s (sample, 50 kg)",
     0.0, experiment_e2_relaxation, false},
    {"e3.1", "e3_1_isometric", "isometric: Biceps Short held at 330 N against 100 kg (arm)", 0.0,
     experiment_e3_isometric, false},
    {"e3.2", "e3_2_isotonic", "isotonic: Biceps Short at 350 N lifts 5 kg, then lets go (arm)", 0.0,
     experiment_e3_isotonic, false},
    {"e4", "e4_summation", "summation and tetanus: one pulse, two pulses, a train at 8 Hz (arm, 5 kg)",
     EXPERIMENT_MAX_PULSE_WIDTH, experiment_e4_summation, false},
    {"c1", "c1_hill_curves",
     "the Hill curves: the original tables (linear, Steffen) and the MATLAB worksheet's analytic set", 0.0,
     experiment_c1_hill_curves, false},
    {"p1", "p1_twitch_tetanus",
     "isometric twitch and tetanus: Biceps Long held at rest length, 2 ms pulses, trains of 1-400 Hz",
     EXPERIMENT_P1_MAX_PULSE_WIDTH, experiment_p1_twitch_tetanus, true},
    {"r1", "r1_recruitment", "recruitment: the worm's motor pool, exertion against recruited neurons", 0.0,
     experiment_r1_recruitment, false},
    {"loop", "loop_round_trip",
     "round trip on the arm: a known pattern, its motion, inverse dynamics, static optimization, a run with the "
     "activations found",
     0.0, experiment_loop_round_trip, false},
};
const int experiment_count = sizeof experiment_list / sizeof experiment_list[0];

const char *const experiment_dynamics_names[] = {"first_order", "fast", "slow", NULL};
