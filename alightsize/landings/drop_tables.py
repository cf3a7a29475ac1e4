"""Drop tests of the articulated-leg test model, AFFDL-TR-66-33 Sec. VI (Table 5, Sec. VI.A-D, Tables 6-13) and
App. VI (test model, test technique).

Transcribed from the published report (cited by section, table, equation and appendix), values as printed, in
the printed units (ft, ft/s, deg, lb, ft-lb, slug ft^2); the unit is in each key name. Misprints are kept as
printed and listed in MISPRINTS; `corrected_strokes_energies()` applies the corrections in CORRECTIONS to a copy.
docs/notes/drop-test-data.md explains the tables, the conventions and how to turn a drop into a scene.

- Table 5: initial conditions of drops 1-6 and 8-11 (no drop 7, deleted for binding of the
  parallelogram load pads, Sec. VI.B, Drop 7; Sec. VI.D). Columns ROLL R, YAW Y, PITCH P (program inputs, deg, 3-2-1
  from the vertical frame kappa), VERTICAL INCLINATION theta (= acos(cos Y cos P)), TERRAIN SLOPE gamma, TRANSLATIONAL
  VELOCITIES V1 (cross), V2 (horizontal), V3 (vertical, + up) ft/s. The slope column is blank for drops 2-9 and
  holds a down arrow for drop 10; V1 is blank for drops 2-10 and a down arrow for drop 11: the arrows are the
  ends of printed "ditto" lines carrying the 0. of drop 1 down the column (read here as 0.0; the printed cell is
  kept in "printed"). No roll-rate column: the rates are zero (not printed).
- Tables 6-13: per drop, per leg 1-4, per cell (upper = parallelogram / psi cell, lower =
  peg-leg / alpha cell) the permanent stroke (ft) and absorbed energy (ft-lb), experimental (post-drop
  measurement; energy = mean static crushing force x permanent deflection, Sec. VI.D) and analytical (digital
  simulation; energy corrected for the different loading and unloading slopes, Sec. VI.D), with the totals and
  "Percent Error" = (total - drop energy) / drop energy. Drops 5, 7 and 11 have no table (Sec. VI.D).
- Sec. VI.A and App. VI (Test Model; Test Technique): how the cell forces were set; no per-drop force is
  printed. CELL_FORCES quotes the text; `implied_static_force()` recovers the measured mean static crushing force
  of each cell from the experimental columns (derived, not printed).
"""

from __future__ import annotations

import copy
import math
import statistics

LEGS = (1, 2, 3, 4)
CELLS = ("upper", "lower")       # upper = parallelogram (psi) cell, lower = peg-leg (alpha) cell

# ------------------------------------------------------------------ App. VI test model (Table 27)
TEST_MODEL = {
    "total_weight_lb": 228.7,                     # App. VI, Test Model "228.7 lb (including legs)"
    "legs_weight_lb": 31.2,                       # App. VI, Test Model "Leg Weight 31.2 lb" (the four legs together)
    "pitch_yaw_inertia_slug_ft2": 3.326,          # App. VI, Test Model "Pitch and Yaw Inertia"
    "roll_inertia_slug_ft2": 2.77,                # App. VI, Test Model "Roll Inertia"
    "cg_above_lower_parallelogram_pivots_ft": 0.33,   # App. VI, Test Model "0.33 feet above lower parallelogram
                                                      # pivots and on the vertical axis"
    "legs": 4,                                    # App. VI (four legs; numbering of Fig. 14, Sec. VI.B, Drop 2)
    "length_scale_to_3000_lb": 4.0,               # Table 27; App. V, articulated leg, test model (configs 3-5, 7)
    "length_scale_to_300_lb": 1.825,              # Table 27; App. V, articulated leg, test model (config 9)
    # App. V: per-leg assembly weights of the test model, lb (Table 23; total printed 6.71)
    "leg_assembly_weights_lb": {
        "Lower Truss": 1.27,                      # Table 23
        "Upper Truss": 0.82,                      # Table 23
        "Parallelogram Absorber": 1.22,           # Table 23
        "Parallelogram Post": 2.30,               # Table 23 (App. V's eq. 107 scalings of the post, the remainder
                                                  # of post and the absorber rod use 2.07)
        "Peg Leg": 1.10,                          # Table 23
    },
    "leg_assembly_total_lb": 6.71,                # Table 23
    # App. V eq. 107 test-model member data (steel, 0.283 lb/in^3): cross-section areas, in^2
    "member_material_density_lb_in3": 0.283,      # App. V, configs 3-5, 7, Upper Truss (rho_TM)
    "upper_truss_area_in2": 0.0984,               # App. V, configs 3-5, 7, Upper Truss
    "lower_truss_area_in2": 0.065,                # App. V, configs 3-5, 7, Lower Truss
    "peg_leg_strut_area_in2": 0.078,              # App. V, configs 3-5, 7, Peg Leg Strut
    "peg_leg_absorber_rod_area_in2": 0.045,       # App. V, configs 3-5, 7, Peg Leg Energy Absorber Rod and Link
    # App. IV: test-model peg-leg ring section, scaled x4 (and x1.14 radially) for configs 3-5, 7 (App. IV, configs
    # 3-5, 7, Peg Leg Ring)
    "peg_leg_ring_inertia_in4": 0.117,            # App. IV, config 9, Peg Leg Ring "0.117 (1.825)^3 (0.432)"
    "peg_leg_ring_c_in": 0.70,                    # App. IV, config 9, Peg Leg Ring "0.70 (1.825)"
}
TEST_MODEL_LINES = {
    "total_weight_lb": 5224, "legs_weight_lb": 5225, "pitch_yaw_inertia_slug_ft2": 5226,
    "roll_inertia_slug_ft2": 5227, "cg_above_lower_parallelogram_pivots_ft": 5228, "legs": 5216,
    "length_scale_to_3000_lb": 5243, "length_scale_to_300_lb": 5243, "leg_assembly_weights_lb": 4909,
    "leg_assembly_total_lb": 4914, "member_material_density_lb_in3": 4921, "upper_truss_area_in2": 4921,
    "lower_truss_area_in2": 4926, "peg_leg_strut_area_in2": 4931, "peg_leg_absorber_rod_area_in2": 4961,
    "peg_leg_ring_inertia_in4": 4656, "peg_leg_ring_c_in": 4658,
}

# Derived, NOT printed: the test model is configuration 3's leg at 1/4 scale (App. V, articulated leg, test model:
# "length scale factor from the test model to configuration numbers 3, 4, 5 and 7 is 4.0"), so the printed full-scale
# dimensions (Sec. III.B.1) give these. The test model's initial psi is not printed; -15 deg is "the test configuration"
# angle of Sec. III.B.1 (inferred).
TEST_MODEL_DERIVED = {
    "parallelogram_member_length_AU_in": 44.0 / 4,        # 11.0 (AU 44 in, Sec. III.B.1)
    "parallelogram_pivot_spacing_AD_in": 24.0 / 4,        # 6.0 (AD 24 in, GUIDE / Sec. III)
    "peg_leg_length_AL_in": 25.0 / 4,                     # 6.25 (Sec. III.B.1)
    "fulcrum_ring_diameter_in": 16.0 / 4,                 # 4.0 (Sec. III.B.1)
    "flat_drop_bottom_clearance_in": 25.0 / 4,            # 6.25 (Sec. III.B.1, at psi0 -15 deg)
    "initial_psi_deg": -15.0,                             # Sec. III.B.1 (inferred for the test model)
    "capsule_weight_without_legs_lb": 228.7 - 31.2,       # 197.5; x15.2 = 3002 lb, x1.52 = 300.2 lb (Table 27)
    "mass_slug": 228.7 / 32.174,                          # 7.108
}

# Table 27, the factors used to scale the test model. "Mass Density 2.5" (300 lb) is 0.25 (GUIDE).
SCALE_FACTORS = {
    #                    3000 lb  300 lb
    "acceleration":       (1.0,    1.0),
    "length":             (4.0,    1.825),
    "mass":               (15.2,   1.52),
    "angular_velocity":   (0.5,    0.739),
    "energy":             (60.8,   2.78),
    "force":              (15.2,   1.52),
    "mass_density":       (0.238,  2.5),     # printed 2.5; 1.52 / 1.825^3 = 0.250 (GUIDE)
    "moment_of_inertia":  (243.0,  5.08),
    "pressure_stress":    (0.95,   0.455),
    "spring_rate":        (3.8,    0.833),
    "time":               (2.0,    1.35),
    "velocity":           (2.0,    1.35),
}

# ------------------------------------------------------------------ Table 5
# Printed cells in column order R, Y, P, theta, gamma, V1, V2, V3 ("" = blank; "↓" = arrow head of a ditto line).
_T5_PRINTED = {
    1: (2250, ("0.", "0.", "0.", "0.", "0.", "0.", "0.", "-17.5")),
    2: (2251, ("0.", "11.5", "-6.", "13.", "", "", "0.", "-17.5")),
    3: (2252, ("-90.", "-3.", "0.", "3.", "", "", "7.5", "-17.5")),
    4: (2253, ("90.", "11.", "-4.", "11.7", "", "", "7.5", "-17.5")),
    5: (2254, ("0.", "6.", "2.", "6.3", "", "", "0.", "-24.")),
    6: (2255, ("0.", "0.", "0.", "0.", "", "", "0.", "-25.3")),
    8: (2256, ("0.", "-12.", "-4.", "12.6", "", "", "0.", "-25.3")),
    9: (2257, ("40.", "0.", "-2.", "2.0", "", "", "8.65", "-25.3")),
    10: (2258, ("90.", "8.", "-4.", "8.9", "↓", "", "7.35", "-25.3")),
    11: (2259, ("45.", "-6.", "6.03", "8.5", "22.", "↓", "-4.5", "-27.2")),
}


def _num(cell: str) -> float:
    return 0.0 if cell in ("", "↓") else float(cell)


# Text of Sec. VI.B per drop (line, what it adds to Table 5).
_DROP_TEXT = {
    1: (2283, "downward velocity, no capsule inclination; single-coordinate motion in the simulation"),
    2: (2330, "pitched 13 deg down relative to the vertical velocity; leg contact order 1, 2, 4, 3"),
    3: (2336, "horizontal and vertical velocity, slight pitch; film pitch possibly ~2 deg low (Fig. 49 step)"),
    4: (2342, "large capsule pitch with horizontal and vertical velocity"),
    5: (2346, "vertical velocity raised from 17.5 to 24.0 ft/s to fully stroke the parallelograms; inclination "
              "6.3 deg, no horizontal velocity; capsule bottom hit the asphalt at 8 ft/s (1 ft free fall) with 89 % "
              "of the kinetic energy absorbed (Sec. VI.B, Drop 5); no stroke table (Sec. VI.D)"),
    6: (2503, "vertical velocity only; all four legs contacted simultaneously"),
    8: (2511, "vertical velocity, inclination about 12 deg; touchdown 3, 4, 2, 1 with 4 and 2 almost simultaneous; "
              "repeat of drop 7 after a design change to the loading pads (Sec. VI.B)"),
    9: (2517, "largest horizontal velocity, 8.65 ft/s instead of the normal 7.5 (33 % more horizontal kinetic "
              "energy); flat drop intended, film shows 2 deg; about 2 deg more would reproduce the two steps of "
              "Fig. 83"),
    10: (2523, "horizontal and vertical velocity with a 9 deg capsule inclination"),
    11: (2640, "22 deg slope; release mis-programmed: horizontal velocity low, vertical high, pitched into the "
               "slope 8.5 deg; the capsule tumbled backward down the slope; simulated with increased cell forces; "
               "stable at 7.8 deg inclination (Sec. VI.B, Drop 11); no stroke table (Sec. VI.D)"),
}

# Cargo / scale (Sec. VI.B): drops 1-5 human cargo, 20 g limit; drops 6-11 electronic cargo, 50 g limit. The
# "soft"/"hard" lander of App. VI (Test Model) is the same model with different honeycomb forces; that drops 1-5
# model the 3000 lb capsule (configs 3-8) and 6-11 the 300 lb capsule (config 9) is inferred from the cargo
# (Sec. II.A) and the cell forces implied by Tables 6-13 (see implied_static_force()).
_CARGO = {d: ("human", 20.0, "3000 lb") if d <= 5 else ("electronic", 50.0, "300 lb")
          for d in (1, 2, 3, 4, 5, 6, 8, 9, 10, 11)}

# Leading leg(s) and contact order computed (NOT printed, except drops 2 and 8) from Table 5 with legs on the
# body axes (leg i at azimuth (i-1)*90 deg from +chi-1 toward +chi-2, docs/notes/telescoping-scene-data.md 2.2),
# LKX of eq. 2 and LEPK of eq. 1 as in the FORTRAN: foot height above the terrain ~ -sin(Y) x + cos(Y) sin(P) y
# (+ the slope term for drop 11); legs within 0.01 of the foot radius of each other are grouped.
_CONTACT_ORDER_COMPUTED = {
    1: ((1, 2, 3, 4),), 2: ((1,), (2,), (4,), (3,)), 3: ((3,), (2, 4), (1,)), 4: ((1,), (2,), (4,), (3,)),
    5: ((1,), (4,), (2,), (3,)), 6: ((1, 2, 3, 4),), 8: ((3,), (2,), (4,), (1,)), 9: ((2,), (1, 3), (4,)),
    10: ((1,), (2,), (4,), (3,)), 11: ((3, 4), (1, 2)),
}
_CONTACT_ORDER_PRINTED = {2: ((2330, (1, 2, 4, 3))), 8: ((2511, (3, 4, 2, 1)))}

DROPS = {}
for _d, (_line, _cells) in _T5_PRINTED.items():
    _r, _y, _p, _th, _g, _v1, _v2, _v3 = (_num(c) for c in _cells)
    DROPS[_d] = {
        "line": _line,
        "printed": _cells,
        "roll_deg": _r,                         # ROLL, about kappa-3 first (eq. 2)
        "yaw_deg": _y,                          # YAW, about the once-rotated 2 axis
        "pitch_deg": _p,                        # PITCH, about body chi-1
        "vertical_inclination_deg": _th,        # theta, angle of chi-3 from the vertical
        "slope_deg": _g,                        # gamma (Sec. V.B; eq. 1); "" and "↓" read as 0
        "cross_velocity_ft_s": _v1,             # V1 (+ out of the page, Sec. V.D.4)
        "horizontal_velocity_ft_s": _v2,        # V2 (+ downhill / away from the terrain for gamma > 0, Sec. V.D.4;
                                                # App. VIII)
        "vertical_velocity_ft_s": _v3,          # V3 (+ up, must be negative, Sec. V.D.4)
        "roll_rate_rad_s": 0.0,                 # not printed (no column); all body rates taken as zero
        "surface": ("asphalt, pointed peg-leg tips dug in: non-slipping, simulated with mu > 1,000,000 (Sec. VI.A; "
                    "Sec. III.B.1)"),
        "cargo": _CARGO[_d][0], "g_limit": _CARGO[_d][1],          # Sec. VI.B
        "scaled_capsule": _CARGO[_d][2],                            # inferred (see _CARGO)
        "text_line": _DROP_TEXT[_d][0], "text": _DROP_TEXT[_d][1],
        "contact_order_printed": _CONTACT_ORDER_PRINTED.get(_d, (None, None))[1],
        "contact_order_printed_line": _CONTACT_ORDER_PRINTED.get(_d, (None, None))[0],
        "contact_order_computed": _CONTACT_ORDER_COMPUTED[_d],      # derived, see above
        "energy_table": {1: 6, 2: 7, 3: 8, 4: 9, 6: 10, 8: 11, 9: 12, 10: 13}.get(_d),
    }

DELETED_DROPS = {
    7: ("no Table 5 row, no figures, no table: binding of the parallelogram load pads (Sec. VI.B, Drop 7); "
        "'binding of an energy absorber on leg 4' (Sec. VI.D); drop 8 repeats it after a pad design change"),
}

# Drops with initial conditions but no stroke/energy table (Sec. VI.D).
NO_STROKE_TABLE = {
    5: "simulation stopped when the capsule bottom interfered with the ground; the test model stroked further",
    11: "simulation terminated when the model pitched 60 deg beyond the vertical; the test model tumbled on",
}

# ------------------------------------------------------------------ cell forces: Sec. VI.A and App. VI
CELL_FORCES = {
    "simulation_source": (2261, "Force deflection characteristics of the energy cells for the digital simulation "
                                "were obtained from pre-test static measurements."),
    "one_curve_per_cell_type": (2261, "Since the simulation requires each type of energy cell to have identical "
                                      "characteristics with the other three, the largest crushing force was used "
                                      "for non-inclined alightments and the characteristics of the leading leg for "
                                      "inclined alightments."),
    "dynamic_excess": (2261, "the true force across the energy absorbers was higher during the tests than that "
                             "measured statically prior to the test. On the average, this difference was 23 percent."),
    "air_cushion": (2263, "An increase in apparent crushing force of about five percent could occur due to the air "
                          "cushion"),
    "binding_friction": (2265, "binding of the energy cell loading pads and friction in the parallelogram"),
    "cell_to_cell_variation": (2275, "small (5 percent) variations in crushing force between energy cells ... "
                                     "Angular accelerations as high as 150 radians per second^2"),
    "drop_11": (2640, "the energy cell forces were increased to allow for the dynamic forcing characteristics of "
                      "the energy cells"),
    "soft_and_hard": (5220, "scale model of a 3000 pound and a 300 pound capsule ... both a \"soft\" and \"hard\" "
                            "lander by merely changing the aluminum honeycomb energy cells' crushing force"),
    "measured_per_cell": (5273, "Measure and record individual honeycomb height and crushing force and the energy "
                                "cell in which used."),
    "experimental_energy": (2744, "assuming that the mean static crushing force acted through a distance equal to "
                                  "the permanent deflection"),
    "analytical_energy": (2746, "The energy absorbed due to crushing of the pads in the simulation must be "
                                "corrected for the difference in loading and unloading slopes."),
    "accelerations_20_percent_high": (3032, "some 20 percent higher on the average. Therefore, 20 percent larger "
                                            "forces existed during the drop test than were predicted from the static "
                                            "force deflection characteristics"),
    "suggest_per_cell_curves": (2734, "The existing simulations should therefore be modified to accept different "
                                      "force deflection characteristics for each energy cell."),
}

# Which characteristic Sec. VI.A prescribes per drop (derived from Table 5 and Sec. VI.A): "largest" for the
# non-inclined drops, "leading" (with the leg) for the inclined ones. Drop 9 was intended flat but has 2 deg.
CELL_FORCE_RULE = {
    1: ("largest", None), 6: ("largest", None),
    2: ("leading", 1), 3: ("leading", 3), 4: ("leading", 1), 5: ("leading", 1), 8: ("leading", 3),
    9: ("leading or largest (2 deg, intended flat)", 2), 10: ("leading", 1), 11: ("leading, then raised", (3, 4)),
}

# Expected plateau forces of the test model from the full-scale curves (tests/reference_tables_14_22.CELL_CURVES)
# divided by the Table 27 force factor (derived, not printed): lb.
SCALED_PLATEAU_FORCE_LB = {
    "3000 lb": {"upper": 36_000 / 15.2, "lower": 30_000 / 15.2},    # configs 3-8: 2368, 1974
    "300 lb": {"upper": 6_688 / 1.52, "lower": 5_852 / 1.52},       # config 9: 4400, 3850
}

# ------------------------------------------------------------------ Tables 6-13
def _side(up_s, up_e, lo_s, lo_e, total, pct, lines):
    return {"upper": {"stroke_ft": up_s, "energy_ft_lb": up_e},
            "lower": {"stroke_ft": lo_s, "energy_ft_lb": lo_e},
            "total_energy_ft_lb": total, "percent_error": pct, "lines": lines}


# drop -> {table, lines, drop_energy_ft_lb, experimental, analytical}; tuples are legs 1, 2, 3, 4.
# "lines" of a side: (upper stroke, upper energy, lower stroke, lower energy, total, percent error).
STROKES_ENERGIES = {
    1: {"table": 6, "lines": (2756, 2782), "drop_energy_ft_lb": 1206, "drop_energy_line": 2758,
        "experimental": _side((0.1000, 0.0910, 0.0975, 0.0910), (235, 214, 229, 214),
                              (0.0067, 0.0, 0.0025, 0.0017), (13, 0, 5, 3), 913, -24.3,
                              (2764, 2765, 2767, 2768, 2769, 2770)),
        "analytical": _side((0.1356, 0.1356, 0.1356, 0.1356), (275, 275, 275, 275),
                            (0.0086, 0.0086, 0.0086, 0.0086), (14, 14, 14, 14), 1156, -4.1,
                            (2776, 2777, 2779, 2780, 2781, 2782))},
    2: {"table": 7, "lines": (2784, 2808), "drop_energy_ft_lb": 1232, "drop_energy_line": 2786,
        "experimental": _side((0.0975, 0.0850, 0.0625, 0.0590), (239, 208, 153, 145),
                              (0.0470, 0.0280, 0.0540, 0.007), (92, 55, 127, 13), 1032, -16.2,
                              (2791, 2792, 2794, 2795, 2796, 2797)),       # leg 4 lower "0.007" (3 decimals)
        "analytical": _side((0.1673, 0.1480, 0.0924, 0.1097), (367, 319, 184, 225),
                            (0.0421, 0.0248, 0.0101, 0.0119), (79, 45, 17, 20), 1256, +1.9,
                            (2802, 2803, 2805, 2806, 2807, 2808))},
    3: {"table": 8, "lines": (2812, 2849), "drop_energy_ft_lb": 1428, "drop_energy_line": 2815,
        "experimental": _side((0.0730, 0.2560, 0.1390, 0.0167), (168, 590, 320, 38),
                              (0.0092, 0.0283, 0.0208, 0.0), (19, 59, 44, 0), 1238, -13.3,
                              (2822, 2823, 2827, 2828, 2830, 2832)),
        "analytical": _side((0.0366, 0.1471, 0.2793, 0.1471), (46, 296, 600, 296),
                            (0.0049, 0.0209, 0.0363, 0.0209), (7, 41, 73, 41), 1400, -2.0,
                            (2839, 2840, 2844, 2845, 2847, 2849))},
    4: {"table": 9, "lines": (2851, 2875), "drop_energy_ft_lb": 1480, "drop_energy_line": 2853,
        "experimental": _side((0.1240, 0.0625, 0.0120, 0.0710), (292, 147, 28, 167),
                              (0.1260, 0.0470, 0.0017, 0.0360), (240, 90, 3, 68), 1035, -30.0,
                              (2858, 2859, 2861, 2862, 2863, 2864)),
        "analytical": _side((0.2057, 0.1137, 0.0244, 0.1427), (447, 225, 42, 293),
                            (0.1216, 0.0508, 0.0049, 0.0631), (228, 93, 9, 117), 1454, -1.8,
                            (2869, 2870, 2872, 2873, 2874, 2875))},
    6: {"table": 10, "lines": (2879, 2903), "drop_energy_ft_lb": 2345, "drop_energy_line": 2881,
        "experimental": _side((0.0975, 0.0990, 0.0980, 0.0950), (420, 426, 422, 409),
                              (0.0025, 0.0017, 0.0050, 0.0008), (9, 6, 17, 3), 1712, -27.0,
                              (2886, 2887, 2889, 2890, 2891, 2892)),
        "analytical": _side((0.1523, 0.1523, 0.1523, 0.1523), (578, 578, 578, 578),
                            (0.0086, 0.0086, 0.0086, 0.0086), (26, 26, 26, 26), 2416, +3.0,
                            (2897, 2898, 2900, 2901, 2902, 2903))},
    8: {"table": 11, "lines": (2905, 2939), "drop_energy_ft_lb": 2375, "drop_energy_line": 2907,
        "experimental": _side((0.0367, 0.1020, 0.1080, 0.0920), (161, 449, 475, 405),
                              (0.0042, 0.0025, 0.0440, 0.0033), (15, 9, 153, 11), 1678, -29.4,
                              (2914, 2915, 2919, 2920, 2922, 2923)),
        "analytical": _side((0.1000, 0.1621, 0.1873, 0.1248), (362, 635, 747, 467),
                            (0.0079, 0.0204, 0.0393, 0.0110), (25, 68, 133, 35), 2472, +4.1,
                            (2930, 2931, 2935, 2936, 2938, 2939))},
    9: {"table": 12, "lines": (2943, 2980), "drop_energy_ft_lb": 2626, "drop_energy_line": 2946,
        "experimental": _side((0.1460, 0.1730, 0.0750, 0.0340), (635, 754, 326, 148),
                              (0.0050, 0.0080, 0.0020, 0.0010), (18, 29, 7, 4), 1921, -26.8,
                              (2953, 2954, 2958, 2959, 2961, 2963)),
        # analytical energy rows of upper and lower are swapped as printed (GUIDE; CORRECTIONS)
        "analytical": _side((0.2242, 0.2380, 0.0823, 0.0625), (147, 128, 38, 34),
                            (0.0417, 0.0364, 0.0114, 0.0103), (899, 958, 281, 195), 2680, +2.1,
                            (2970, 2971, 2975, 2976, 2978, 2980))},
    10: {"table": 13, "lines": (2982, 3020), "drop_energy_ft_lb": 2572, "drop_energy_line": 2986,
         "experimental": _side((0.1380, 0.1040, 0.0150, 0.0675), (607, 458, 66, 297),
                               (0.0670, 0.0410, 0.0010, 0.0920), (241, 148, 4, 332), 2153, -16.3,
                               (2993, 2994, 2998, 2999, 3001, 3003)),
         "analytical": _side((0.2425, 0.1513, 0.0425, 0.1342), (982, 588, 109, 511),
                             (0.0620, 0.0291, 0.0032, 0.0267), (220, 105, 9, 93), 2617, +1.8,
                             (3010, 3011, 3015, 3016, 3018, 3020))},
}

# (drop, side, cell, quantity) -> (printed, corrected, reason). Applied only by corrected_strokes_energies().
CORRECTIONS = {
    (9, "analytical", "upper", "energy_ft_lb"): (
        (147, 128, 38, 34), (899, 958, 281, 195),
        "Table 12 analytical energy rows of upper and lower cells swapped (GUIDE): swapped, E ~ F (s - d) fits "
        "upper F 4,275 lb, d 0.014 ft and lower F 3,585 lb, d 0.0007 ft, as drops 6, 8, 10; as printed the upper "
        "cells would absorb 600-650 lb x stroke and the lower 4,000-21,000 lb x stroke"),
    (9, "analytical", "lower", "energy_ft_lb"): (
        (899, 958, 281, 195), (147, 128, 38, 34), "see the upper row (swap); the total 2,680 is unchanged"),
}


def corrected_strokes_energies() -> dict:
    """A deep copy of STROKES_ENERGIES with CORRECTIONS applied (the printed values stay in CORRECTIONS)."""
    out = copy.deepcopy(STROKES_ENERGIES)
    for (drop, side, cell, qty), (printed, fixed, _) in CORRECTIONS.items():
        assert out[drop][side][cell][qty] == printed
        out[drop][side][cell][qty] = fixed
    return out


def implied_static_force(drop: int, leg: int, cell: str) -> tuple[float, float] | None:
    """Derived (not printed): the mean static crushing force (lb) behind one experimental energy, energy / stroke
    (Sec. VI.D defines the energy as that force times the permanent deflection), and its rounding bound from the
    1 ft-lb energy rounding (+-0.5 / stroke). None where the stroke is 0. Within a drop the four cells of a type
    agree to the rounding (one force per drop and cell type; exceptions: drop 2 lower leg 3, drop 9 upper legs
    1/2, MISPRINTS): soft drops 1-4 upper 2,300-2,450 lb, lower 1,900-2,100 lb; hard drops 6-10 upper
    4,300-4,400 lb, lower 3,450-3,600 lb (cf. SCALED_PLATEAU_FORCE_LB)."""
    side = STROKES_ENERGIES[drop]["experimental"][cell]
    s, e = side["stroke_ft"][leg - 1], side["energy_ft_lb"][leg - 1]
    if not s:
        return None
    return e / s, 0.5 / s


# Analytical strokes long enough to carry the fit of simulation_cell_force (ft): past the upper cell's 0.04 ft
# loading ramp of the drop scenes, past the lower cell's 0.005 ft.
FIT_MIN_STROKE_FT = {"upper": 0.03, "lower": 0.004}


def simulation_fit_points(drop: int, cell: str) -> list[tuple[float, float]]:
    """(analytical stroke ft, analytical energy ft-lb) of the cells of one type in a tabled drop whose strokes carry
    the fit of simulation_cell_force (longer than FIT_MIN_STROKE_FT)."""
    tables = corrected_strokes_energies()
    if drop not in tables:
        raise ValueError(f"drop {drop} has no table of strokes and energies (Tables 6-13 cover {sorted(tables)})")
    side = tables[drop]["analytical"][cell]
    return [(s, e) for s, e in zip(side["stroke_ft"], side["energy_ft_lb"]) if s > FIT_MIN_STROKE_FT[cell]]


def simulation_cell_force(drop: int, cell: str) -> tuple[float, str]:
    """Derived (not printed): the crushing force (lb) of one cell type in the report's simulation of a drop with a
    table, and how it was found. Sec. VI.A: the simulation used one measured curve per cell type and
    drop, the largest force for non-inclined drops, the leading leg's for inclined ones. The analytical energies
    follow E = F (s - d) from the analytical strokes s (d: the loading/unloading slope correction, Sec. VI.D), so a
    least-squares line through the cells with enough stroke gives F ("analytical fit"). Drops 1 and 6 stroke all
    four cells alike, which leaves F and d apart undetermined: there F is the mean static crushing force the
    experimental energies imply (`implied_static_force`, Sec. VI.D), weighted by its rounding bound
    ("experimental")."""
    pts = simulation_fit_points(drop, cell)
    if len(pts) >= 2 and max(s for s, _ in pts) - min(s for s, _ in pts) > 1e-3:
        strokes, energies = zip(*pts)
        return statistics.linear_regression(strokes, energies).slope, "analytical fit"
    implied = [f for f in (implied_static_force(drop, leg, cell) for leg in LEGS) if f]
    weights = [1.0 / bound ** 2 for _, bound in implied]
    return sum(w * f for w, (f, _) in zip(weights, implied)) / sum(weights), "experimental"


# ------------------------------------------------------------------ energy closure (Sec. VI.D, Fig. 102)
ENERGY_CLOSURE = {
    # drop: (drop energy, experimental total, printed %, analytical total, printed %)
    d: (t["drop_energy_ft_lb"], t["experimental"]["total_energy_ft_lb"], t["experimental"]["percent_error"],
        t["analytical"]["total_energy_ft_lb"], t["analytical"]["percent_error"])
    for d, t in STROKES_ENERGIES.items()
}
ENERGY_CLOSURE_TEXT = {
    "analytical_mean_abs_percent_below": (0.5, 2750),     # "The average difference is less than 0.5 percent"
    "analytical_max_percent": (4.1, 2750),                # "the largest difference is 4.1 percent"
    "experimental_mean_percent": (22.9, 2750),            # "The average difference is 22.9 percent"
    "experimental_max_percent": (30.0, 2750),
    "experimental_min_percent": (13.3, 2750),
    "static_vs_dynamic_force_percent": (23.0, 2261),      # Sec. VI.A
    "acceleration_excess_percent": (20.0, 3032),
    "figure_102_line": (3024, "Figure 102, Comparison of Energy Absorption (caption only; no data in the OCR)"),
    "drop_energy_definition": (2748, "kinetic energy of the horizontal velocity + weight x (nominal drop height, "
                                     "measured from the lowest leg's contact point, + CG height change due to the "
                                     "nutation angle + CG height change due to the deflection of the alightment "
                                     "system)"),
    "nominal_heights": (3026, "'10 foot drops' (drops 6-11) and '5 foot drops' (drops 1-4)"),
}

G_FT_S2 = 32.174


NOMINAL_DROP_HEIGHT_FT = {1: 5.0, 2: 5.0, 3: 5.0, 4: 5.0, 6: 10.0, 8: 10.0, 9: 10.0, 10: 10.0}   # Sec. VI.D (5 ft
# drops = V3 17.5, 10 ft drops = V3 25.3; drops 5 and 11 have no printed height)


def drop_energy_check(drop: int, weight_lb: float = 228.7) -> dict:
    """Derived: kinetic energy of Table 5's V2 and V3 at impact vs the printed drop energy; the remainder divided
    by the weight is the extra CG fall (nutation + alightment-system deflection terms of Sec. VI.D). Also the same
    remainder over the nominal 5 / 10 ft height instead of V3 ("extra_over_nominal_ft")."""
    c = DROPS[drop]
    m = weight_lb / G_FT_S2
    ke_v = 0.5 * m * c["vertical_velocity_ft_s"] ** 2
    ke_h = 0.5 * m * (c["horizontal_velocity_ft_s"] ** 2 + c["cross_velocity_ft_s"] ** 2)
    e = STROKES_ENERGIES[drop]["drop_energy_ft_lb"] if drop in STROKES_ENERGIES else None
    out = {"free_fall_height_ft": c["vertical_velocity_ft_s"] ** 2 / (2 * G_FT_S2), "ke_vertical_ft_lb": ke_v,
           "ke_horizontal_ft_lb": ke_h, "printed_drop_energy_ft_lb": e}
    if e is not None:
        out["remainder_ft_lb"] = e - ke_v - ke_h
        out["extra_cg_fall_ft"] = (e - ke_v - ke_h) / weight_lb
        out["extra_over_nominal_ft"] = (e - ke_h) / weight_lb - NOMINAL_DROP_HEIGHT_FT[drop]
    return out


def inclination_deg(drop: int) -> float:
    """theta = acos(cos Y cos P) = acos(LKX(3,3)), to compare with the printed VERTICAL INCLINATION."""
    c = DROPS[drop]
    return math.degrees(math.acos(math.cos(math.radians(c["yaw_deg"])) * math.cos(math.radians(c["pitch_deg"]))))


# ------------------------------------------------------------------ misprints and ambiguities
MISPRINTS = [
    {"where": "Table 12 (drop 9) analytical energy rows", "lines": (2971, 2976),
     "printed": "upper 147 128 38 34; lower 899 958 281 195",
     "reading": "upper 899 958 281 195; lower 147 128 38 34 (rows swapped; total 2,680 unchanged)",
     "evidence": "GUIDE; energy/stroke per cell as in drops 6, 8, 10 only after the swap (see CORRECTIONS)"},
    {"where": "Sec. VI.D analytical closure", "lines": (2750,),
     "printed": "The average difference is less than 0.5 percent",
     "reading": "not reproduced: the eight printed Percent Errors average +0.63 % (signed) or 2.6 % (absolute); "
                "unrounded totals give +0.63 % too. Kept as printed; no correction.",
     "evidence": "Tables 6-13 Percent Error rows"},
    {"where": "Drop 8 contact order", "lines": (2511, 2256),
     "printed": "Leg touchdown sequence was 3, 4, 2, 1, with 4 and 2 touching down almost simultaneously",
     "reading": "Table 5 (Y -12, P -4) gives 3, 2, 4, 1 with legs on the body axes (2 before 4 by 0.14 x foot "
                "radius); the text itself calls 2 and 4 almost simultaneous. Not corrected.",
     "evidence": "docs/notes/telescoping-scene-data.md 2.2"},
    {"where": "Table 7 (drop 2) experimental lower stroke leg 4", "lines": (2794,),
     "printed": "0.007", "reading": "0.0070 (three decimals where the rest print four; 13 ft-lb / 0.007 ft = "
                                    "1,857 lb, in line with the other soft lower cells)", "evidence": "format"},
    {"where": "Table 7 (drop 2) experimental lower leg 3", "lines": (2794, 2795),
     "printed": "stroke 0.0540, energy 127",
     "reading": "suspect, not corrected: 127 / 0.0540 = 2,352 lb, where the other drop-2 lower cells give "
                "1,946-1,968 lb (and 2,352 is the drop-1 upper force); a stroke of ~0.0650 ft (127 / 1,955) or an "
                "energy of ~106 ft-lb would fit. The total 1,032 and -16.2 % use 127.",
     "evidence": "implied_static_force()"},
    {"where": "Table 12 (drop 9) experimental upper legs 1 and 2", "lines": (2953, 2954),
     "printed": "0.1460 / 635 and 0.1730 / 754",
     "reading": "implied forces 4,346-4,352 and 4,355-4,361 lb do not overlap (by 3 lb): two cell forces, or a "
                "1 ft-lb rounding slip; immaterial", "evidence": "implied_static_force()"},
    {"where": "Table 5 slope and V1 columns", "lines": (2251, 2259),
     "printed": "blank cells; '↓' in gamma (drop 10) and V1 (drop 11)",
     "reading": "0.0: ends of ditto lines from drop 1's 0. (gamma 0 for drops 1-10, 22 for drop 11; V1 0 for all)",
     "evidence": "the arrows sit on the last row of each blank run; the text speaks of flat asphalt except drop 11 "
                 "(Sec. VI.B, Drop 11) and of in-plane horizontal velocity"},
    {"where": "App. VI leg weight vs App. V test-model leg assemblies", "lines": (5225, 4914),
     "printed": "Leg Weight 31.2 lb; per-leg assemblies total 6.71 lb",
     "reading": "4 x 6.71 = 26.84 lb, 4.36 lb short of 31.2 (honeycomb, rods, caps or fittings presumably not in "
                "the 'assemblies'); not a correction",
     "evidence": "arithmetic"},
    {"where": "App. V parallelogram post test-model weight", "lines": (4912, 4949, 4955, 4961),
     "printed": "Parallelogram Post = 2.30 (assembly list); eq. 107 uses W_TM = 2.07",
     "reading": "unresolved; both kept", "evidence": "arithmetic"},
    {"where": "Percent Error rounding", "lines": (2864, 2923, 3020),
     "printed": "drop 4 experimental -30.0; drop 8 experimental -29.4; drop 10 analytical +1.8",
     "reading": "from the printed totals: -30.07 (-30.1), -29.35 (-29.3), +1.750 (+1.7); within 0.07 %, "
                "presumably computed from unrounded energies; kept as printed",
     "evidence": "(total - drop energy) / drop energy"},
    {"where": "Table 27 300 lb mass density", "lines": (5248,), "printed": "2.5", "reading": "0.25 (GUIDE)",
     "evidence": "1.52 / 1.825^3 = 0.250"},
]
