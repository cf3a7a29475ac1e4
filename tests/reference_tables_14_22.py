"""Printed member-load envelopes of the articulated leg, AFFDL-TR-66-33 App. III, Tables 14-22, and the
cell force-deflection curves of configurations 3-9 (Sec. IV).

Transcribed from the published report (cited by section, table, equation and appendix), values as
printed (lbf, degrees). Each row is (member, load lbf, alpha deg, beta deg, psi deg); tension positive.
Member names are those of `alightsize_sim.articulated_statics.MEMBERS`. The tables label the pairs PL1/(PL3),
PL2/(PL6), PU1/(PU2) and the OCR or the typesetter garbles several labels; they are mapped by row order:

- row 1-2 "PL1,(PL5)" (T14), "PL2,(PL3)" (T16, T20) -> PL1;
- row 3-4 "PL2,(PL4)" (T17, T22) -> PL2;
- row 5-6 "PL1,(PL2)" (T16, T19), "PU2,(PU2)" (T20) -> PU1;
- "R12/13", "R1,2,3" in the R1213 row (T16, T17, T19, T20), "R123" in the R1213 row (T21) -> R1213;
- the psi column is headed "gamma" in Tables 15, 16, 18-21.

Table 20 prints each member's tension and compression on one line ("+3,100 -3,715  1.0 1.0  -40. +130.
+30. -13."); they are split into two rows here. Tables 20, 21 and 22 print a single, positive RA and RB
(and no sign pair); those rows are listed in MAGNITUDE_ONLY: compare the magnitude, and the position with
whichever extreme (tension or compression) lies there.

Suspected misprints (evidence from the other tables; the rows above keep the printed numbers):

- T14 Q2 compression -10,895 at (2, 180, +15): the same value is printed at psi = -15 by T15, T16, T17
  and T20 (scaled by the lower-cell force ratio 5,852/30,000: 2,126 = 0.1951 x 10,895), the position where
  the upper cell is still unloaded (AF1 = 0); +15 is -15 (and alpha 2 likely 20, T15, T17, T20).
- PU1 tension 12,790 and Q2 compression 10,895 (the AF1 = 0 extremes at psi -15) are printed at alpha 20 by
  T14 (PU1), T15 (Q2), T17 and T20 (config 9 = config 5 scaled) but at alpha 2 by T14 (Q2), T15 (PU1) and
  T16: a dropped "0" or a near tie (the load is nearly flat in alpha there). T16 RA +-14,576 at alpha 1.0
  repeats T15's value (config 4, alpha 10); config 9 prints alpha 15 for RA (flat in alpha as well).
- T21 (combined 3, 4, 5, 7) R1213 = 16,135 and R123 = 63,977 are configuration 6's values (T17/T22);
  the largest of configs 3, 4, 5, 7 are 13,317 and 50,762 (T16). T21 Q1 +36,322 is config 7's value but
  printed at psi -13 (T18: -15); T21 Q1 -29,420 is config 5's value but at alpha 2.0 (T16: 1.0); T21 PL1
  +16,022 at alpha 2.0 (T16: 1.0); T21 PU1 +12,974 at alpha 2.0 (T18: 20.0).
- T22 (combined 6, 8) Q2 compression -10,601 is config 8's value at psi -10 although config 6 prints a
  larger compression, -10,895 (T17).
- T21 and T22 RB: one positive value printed at beta +90, where the component tables have the negative one.
- T17 and T19 (configs 6, 8) print PL1 compression at beta +120 (the other tables +130).
- T19 (config 8) PU1 tension 12,637 at psi -10 and Q2 compression 10,601 at psi -10 are the AF1 = 0
  extremes of that configuration's own initial angle (-10 deg), consistent with T18 (-20 deg): not misprints.
"""

# ------------------------------------------------------------------ Tables 14-20, one configuration each
TABLES = {
    "3": (                                   # Table 14 (initial psi -15)
        ("PL1", +15_790, 2.0, -40.0, +30.0),
        ("PL1", -18_462, 2.0, +130.0, -5.0),
        ("PL2", +15_285, 2.0, -60.0, +30.0),
        ("PL2", -17_422, 2.0, +110.0, -5.0),
        ("PU1", +12_790, 20.0, +120.0, -15.0),
        ("PU1", -32_566, 15.0, -60.0, -5.0),
        ("RA", +14_345, 15.0, +90.0, -5.0),
        ("RA", -14_345, 15.0, -90.0, -5.0),
        ("RB", +25_808, 2.0, -90.0, -5.0),
        ("RB", -25_808, 2.0, +90.0, -5.0),
        ("Q1", +33_606, 2.0, +180.0, -5.0),
        ("Q1", -28_871, 2.0, 0.0, +30.0),
        ("Q2", +42_978, 2.0, 0.0, +30.0),
        ("Q2", -10_895, 2.0, +180.0, +15.0),     # psi +15 suspected for -15 (module docstring)
        ("R1213", +12_972, 2.0, 0.0, +30.0),
        ("R11", +48_759, 2.0, 0.0, +30.0),
        ("R123", +50_455, 2.0, 0.0, +30.0),
    ),
    "4": (                                   # Table 15
        ("PL1", +15_790, 2.0, -40.0, +30.0),
        ("PL1", -19_291, 2.0, +130.0, -13.0),
        ("PL2", +15_285, 2.0, -60.0, +30.0),
        ("PL2", -17_976, 2.0, +110.0, -13.0),
        ("PU1", +12_790, 2.0, +120.0, -15.0),
        ("PU1", -33_508, 15.0, -60.0, -13.0),
        ("RA", +14_576, 10.0, +90.0, -13.0),
        ("RA", -14_576, 10.0, -90.0, -13.0),
        ("RB", +26_232, 2.0, -90.0, -13.0),
        ("RB", -26_232, 2.0, +90.0, -13.0),
        ("Q1", +35_677, 2.0, +180.0, -13.0),
        ("Q1", -28_871, 2.0, 0.0, +30.0),
        ("Q2", +42_978, 2.0, 0.0, +30.0),
        ("Q2", -10_895, 20.0, +180.0, -15.0),
        ("R1213", +12_972, 2.0, 0.0, +30.0),
        ("R11", +48_759, 2.0, 0.0, +30.0),
        ("R123", +50_455, 2.0, 0.0, +30.0),
    ),
    "5": (                                   # Table 16 (labels misprinted, see docstring)
        ("PL1", +16_022, 1.0, -40.0, +30.0),
        ("PL1", -19_459, 1.0, +130.0, -13.0),
        ("PL2", +15_455, 1.0, -60.0, +30.0),
        ("PL2", -18_126, 1.0, +110.0, -13.0),
        ("PU1", +12_790, 2.0, +120.0, -15.0),
        ("PU1", -33_508, 15.0, -60.0, -13.0),
        ("RA", +14_576, 1.0, +90.0, -13.0),
        ("RA", -14_576, 1.0, -90.0, -13.0),
        ("RB", +26_448, 1.0, -90.0, -13.0),
        ("RB", -26_448, 1.0, +90.0, -13.0),
        ("Q1", +35_988, 1.0, +180.0, -13.0),
        ("Q1", -29_420, 1.0, 0.0, +30.0),
        ("Q2", +43_076, 1.0, 0.0, +30.0),
        ("Q2", -10_895, 2.0, +180.0, -15.0),
        ("R1213", +13_317, 1.0, 0.0, +30.0),
        ("R11", +48_984, 1.0, 0.0, +30.0),
        ("R123", +50_762, 1.0, 0.0, +30.0),
    ),
    "6": (                                   # Table 17
        ("PL1", +18_338, 2.0, -40.0, +30.0),
        ("PL1", -24_163, 2.0, +120.0, +8.0),
        ("PL2", +18_315, 2.0, -60.0, +30.0),
        ("PL2", -22_392, 2.0, +110.0, +8.0),
        ("PU1", +12_790, 20.0, +120.0, -15.0),
        ("PU1", -50_715, 2.0, -60.0, +8.0),
        ("RA", +17_912, 6.0, +90.0, +8.0),
        ("RA", -17_912, 6.0, -90.0, +8.0),
        ("RB", +32_289, 2.0, -90.0, +8.0),
        ("RB", -32_289, 2.0, +90.0, +8.0),
        ("Q1", +45_391, 2.0, +180.0, +8.0),
        ("Q1", -31_935, 2.0, 0.0, +30.0),
        ("Q2", +71_366, 2.0, 0.0, +30.0),
        ("Q2", -10_895, 20.0, +180.0, -15.0),
        ("R1213", +16_135, 2.0, 0.0, +30.0),
        ("R11", +61_909, 2.0, 0.0, +30.0),
        ("R123", +63_977, 2.0, 0.0, +30.0),
    ),
    "7": (                                   # Table 18 (initial psi -20)
        ("PL1", +15_790, 2.0, -40.0, +30.0),
        ("PL1", -19_532, 2.0, +130.0, -15.0),
        ("PL2", +15_285, 2.0, -60.0, +30.0),
        ("PL2", -18_130, 2.0, +110.0, -15.0),
        ("PU1", +12_974, 20.0, +120.0, -20.0),
        ("PU1", -33_784, 15.0, -60.0, -15.0),
        ("RA", +14_639, 10.0, +90.0, -15.0),
        ("RA", -14_639, 10.0, -90.0, -15.0),
        ("RB", +26_348, 2.0, -90.0, -15.0),
        ("RB", -26_348, 2.0, +90.0, -15.0),
        ("Q1", +36_322, 2.0, +180.0, -15.0),
        ("Q1", -28_871, 2.0, 0.0, +30.0),
        ("Q2", +43_254, 25.0, 0.0, -15.0),
        ("Q2", -11_298, 15.0, +180.0, -20.0),
        ("R1213", +12_972, 2.0, 0.0, +30.0),
        ("R11", +48_759, 2.0, 0.0, +30.0),
        ("R123", +50_455, 2.0, 0.0, +30.0),
    ),
    "8": (                                   # Table 19 (initial psi -10)
        ("PL1", +18_338, 2.0, -40.0, +30.0),
        ("PL1", -24_163, 2.0, +120.0, +8.0),
        ("PL2", +18_315, 2.0, -60.0, +30.0),
        ("PL2", -22_392, 2.0, +110.0, +8.0),
        ("PU1", +12_637, 20.0, +120.0, -10.0),
        ("PU1", -50_715, 2.0, -60.0, +8.0),
        ("RA", +17_912, 6.0, +90.0, +8.0),
        ("RA", -17_912, 6.0, -90.0, +8.0),
        ("RB", +32_290, 2.0, -90.0, +8.0),
        ("RB", -32_290, 2.0, +90.0, +8.0),
        ("Q1", +45_391, 2.0, +180.0, +8.0),
        ("Q1", -31_935, 2.0, 0.0, +30.0),
        ("Q2", +71_366, 2.0, 0.0, +30.0),
        ("Q2", -10_601, 20.0, +180.0, -10.0),
        ("R1213", +16_135, 2.0, 0.0, +30.0),
        ("R11", +61_909, 2.0, 0.0, +30.0),
        ("R123", +63_977, 2.0, 0.0, +30.0),
    ),
    "9": (                                   # Table 20 (two rows per printed line)
        ("PL1", +3_100, 1.0, -40.0, +30.0),
        ("PL1", -3_715, 1.0, +130.0, -13.0),
        ("PL2", +2_983, 1.0, -60.0, +30.0),
        ("PL2", -3_467, 1.0, +110.0, -13.0),
        ("PU1", +2_491, 20.0, +120.0, -15.0),
        ("PU1", -6_340, 15.0, -60.0, -13.0),
        ("RA", +2_805, 15.0, +90.0, -13.0),      # one sign printed (MAGNITUDE_ONLY)
        ("RB", +5_086, 1.0, +90.0, -13.0),       # one sign printed; at beta +90 RB is compressive in T14-19
        ("Q1", +6_861, 1.0, +180.0, -13.0),
        ("Q1", -5_720, 1.0, 0.0, +30.0),
        ("Q2", +8_147, 1.0, 0.0, +30.0),
        ("Q2", -2_126, 20.0, +180.0, -15.0),
        ("R1213", +2_568, 1.0, 0.0, +30.0),
        ("R11", +9_436, 1.0, 0.0, +30.0),
        ("R123", +9_779, 1.0, 0.0, +30.0),
    ),
    # ---------------------------------------------------------- Tables 21-22, combined envelopes
    "3457": (                                # Table 21
        ("PL1", +16_022, 2.0, -40.0, +30.0),
        ("PL1", -19_532, 2.0, +130.0, -15.0),
        ("PL2", +15_455, 1.0, -60.0, +30.0),
        ("PL2", -18_130, 2.0, +110.0, -15.0),
        ("PU1", +12_974, 2.0, +120.0, -20.0),
        ("PU1", -33_784, 15.0, -60.0, -15.0),
        ("RA", +14_639, 10.0, +90.0, -15.0),     # one sign printed
        ("RB", +26_448, 1.0, +90.0, -13.0),      # one sign printed
        ("Q1", +36_322, 2.0, +180.0, -13.0),
        ("Q1", -29_420, 2.0, 0.0, +30.0),
        ("Q2", +43_254, 25.0, 0.0, -15.0),
        ("Q2", -11_298, 15.0, +180.0, -20.0),
        ("R1213", +16_135, 2.0, 0.0, +30.0),     # printed "R123"; config 6's value (docstring)
        ("R11", +48_984, 1.0, 0.0, +30.0),
        ("R123", +63_977, 2.0, 0.0, +30.0),      # config 6's value (docstring)
    ),
    "68": (                                  # Table 22
        ("PL1", +18_338, 2.0, -40.0, +30.0),
        ("PL1", -24_163, 2.0, +120.0, +8.0),
        ("PL2", +18_315, 2.0, -60.0, +30.0),
        ("PL2", -22_392, 2.0, +110.0, +8.0),
        ("PU1", +12_790, 20.0, +120.0, -15.0),
        ("PU1", -50_715, 2.0, -60.0, +8.0),
        ("RA", +17_912, 6.0, +90.0, +8.0),       # one sign printed
        ("RB", +32_290, 2.0, +90.0, +8.0),       # one sign printed
        ("Q1", +45_391, 2.0, +180.0, +8.0),
        ("Q1", -31_935, 2.0, 0.0, +30.0),
        ("Q2", +71_366, 2.0, 0.0, +30.0),
        ("Q2", -10_601, 20.0, +180.0, -10.0),    # config 8's; config 6 prints -10,895 (docstring)
        ("R1213", +16_135, 2.0, 0.0, +30.0),
        ("R11", +61_909, 2.0, 0.0, +30.0),
        ("R123", +63_977, 2.0, 0.0, +30.0),
    ),
}

TABLE_NUMBER = {"3": 14, "4": 15, "5": 16, "6": 17, "7": 18, "8": 19, "9": 20, "3457": 21, "68": 22}

# Combined tables: the configurations they envelope (eqs. 105-106).
COMBINED = {"3457": ("3", "4", "5", "7"), "68": ("6", "8")}

# (configuration, member) whose printed load is a magnitude (single positive RA / RB row).
MAGNITUDE_ONLY = {("9", "RA"), ("9", "RB"), ("3457", "RA"), ("3457", "RB"), ("68", "RA"), ("68", "RB")}

# (configuration, member, sign) -> (corrected row, reason): positions (or values) that the other tables show
# to be misprinted. Used only where a caller asks for corrected positions; TABLES stays as printed.
SUSPECTED_MISPRINTS = {
    ("3", "Q2", -1): (("Q2", -10_895, 20.0, +180.0, -15.0),
        "T14 psi +15 (and alpha 2): T15-T17, T20 print (20, 180, -15)"),
    ("4", "PU1", +1): (("PU1", +12_790, 20.0, +120.0, -15.0), "T15 alpha 2.0: T14, T17, T20 print 20"),
    ("5", "PU1", +1): (("PU1", +12_790, 20.0, +120.0, -15.0), "T16 alpha 2.0: T14, T17, T20 print 20"),
    ("5", "Q2", -1): (("Q2", -10_895, 20.0, +180.0, -15.0), "T16 alpha 2.0: T15, T17, T20 print 20"),
    ("3457", "R1213", +1): (("R1213", +13_317, 1.0, 0.0, +30.0),
        "T21 prints config 6's 16,135; max of 3,4,5,7 is T16's"),
    ("3457", "R123", +1): (("R123", +50_762, 1.0, 0.0, +30.0), "T21 prints config 6's 63,977; max of 3,4,5,7 is T16's"),
    ("3457", "Q1", +1): (("Q1", +36_322, 2.0, +180.0, -15.0), "T21 psi -13: the value is config 7's, at -15 (T18)"),
    ("3457", "Q1", -1): (("Q1", -29_420, 1.0, 0.0, +30.0), "T21 alpha 2.0: the value is config 5's, at alpha 1 (T16)"),
    ("3457", "PL1", +1): (("PL1", +16_022, 1.0, -40.0, +30.0),
        "T21 alpha 2.0: the value is config 5's, at alpha 1 (T16)"),
    ("3457", "PU1", +1): (("PU1", +12_974, 20.0, +120.0, -20.0),
        "T21 alpha 2.0: the value is config 7's, at alpha 20 (T18)"),
    ("68", "Q2", -1): (("Q2", -10_895, 20.0, +180.0, -15.0),
        "T22 prints config 8's -10,601; config 6's -10,895 is larger"),
}

# ------------------------------------------------------------------ cell force-deflection curves, Sec. IV.A
# configuration -> (upper (deflection ft, force lbf) points, lower points, initial psi deg).
# Upper = parallelogram cell (psi), lower = peg-leg cell (alpha); loading branch as printed.
CELL_CURVES = {
    "3": (((0.00, 0), (0.16, 36_000), (0.97, 36_000), (1.00, 72_000)),            # Sec. IV.A, configuration 3
          ((0.00, 0), (0.02, 30_000), (0.40, 30_000), (0.50, 60_000)), -15.0),
    "4": (((0.00, 0), (0.04, 36_000), (0.97, 36_000), (1.00, 72_000)),            # Sec. IV.A, configuration 4
          ((0.00, 0), (0.02, 30_000), (0.40, 30_000), (0.50, 60_000)), -15.0),
    "5": (((0.00, 0), (0.04, 36_000), (0.97, 36_000), (1.00, 72_000)),            # Sec. IV.A, configuration 5
          ((0.000, 0), (0.005, 30_000), (0.400, 30_000), (0.500, 60_000)), -15.0),
    "6": (((0.00, 0), (0.16, 36_000), (0.47, 36_000), (0.51, 72_000), (0.97, 72_000), (1.00, 144_000)),  # Sec. IV.A
          ((0.00, 0), (0.02, 30_000), (0.40, 30_000), (0.50, 60_000)), -15.0),
    "7": (((0.00, 0), (0.04, 36_000), (1.10, 36_000), (1.13, 72_000)),            # Sec. IV.A, configuration 7
          ((0.00, 0), (0.02, 30_000), (0.40, 30_000), (0.50, 60_000)), -20.0),
    "8": (((0.00, 0), (0.04, 36_000), (0.35, 36_000), (0.39, 72_000), (0.85, 72_000), (0.88, 144_000)),  # Sec. IV.A
          ((0.00, 0), (0.02, 30_000), (0.40, 30_000), (0.50, 60_000)), -10.0),
    "9": (((0.000, 0), (0.018, 6_688), (0.443, 6_688), (0.456, 13_376)),          # Sec. IV.A, configuration 9 (300 lb
                                                                                  # capsule)
          ((0.00000, 0), (0.00228, 5_852), (0.18250, 5_852), (0.22800, 11_700)), -15.0),
}

# Configuration 9 is the full-scale leg scaled in length by 1.825 / 4 (Sec. III, Sec. III.B.2; App. VI Table 27).
CONFIG_9_LENGTH_SCALE = 1.825 / 4
