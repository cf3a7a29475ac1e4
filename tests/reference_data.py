"""Printed results of AFFDL-TR-66-33 App. IV (stress design factors) and App. V (weights, Tables 23-26).

Transcribed from the published report (cited by section, table, equation and appendix), as printed,
misprints included. Units as printed: lb, lb/in^2 (psi), in. Configuration ids are those of the example configs:
"012" telescoping, "3457", "68" and "9" articulated.
"""

# ------------------------------------------------------------------ App. IV design factors
# (configuration, item name, check kind) -> (printed f, printed allowable psi, printed stress psi).
# The allowable is the yield (or yield / 2 where the check is a maximum-shear one); the stress is the one f
# is computed from. pin_shear is on loads: allowable = bolt capacity (lb), stress = resultant load (lb).
DESIGN_FACTORS = {
    # Telescoping leg, configurations 0, 1, 2
    ("012", "Lower Leg Tube", "combined"): (1.26, 74_000, 58_600),          # App. IV: 74,000/58,600
    ("012", "Lower Leg Cap", "plate_fixed_center_load"): (1.25, 34_500, 27_500),    # App. IV: (69,000/2)/27,500
    ("012", "Upper and Lower Plates", "plate_supported_center_load"): (1.24, 34_500, 28_100),  # App. IV
    ("012", "Upper Leg Tube", "combined"): (1.42, 74_000, 52_020),          # App. IV: 74,000/52,020
    ("012", "Double Pin Swivel", "pin_shear"): (2.37, 9_300, 3_930),        # App. IV: 9,300 lb / 3,930 lb
    ("012", "Double Pin Swivel", "combined"): (2.20, 180_000, 81_600),      # App. IV: 180,000/81,600
    ("012", "Upper Leg Cap", "plate_fixed_center_moment_and_load"): (1.53, 34_500, 22_490),  # App. IV
    ("012", "Upper Cap Lugs", "bearing"): (1.75, 69_000, 39_400),           # App. IV: 69,000/39,400
    ("012", "Upper Cap Lugs", "combined"): (1.42, 69_000, 48_800),          # App. IV: 69,000/48,800
    # Articulated leg, configurations 3, 4, 5 and 7
    ("3457", "Upper Truss", "compression"): (1.24, 74_000, 59_700),         # App. IV
    ("3457", "Lower Truss", "compression"): (1.25, 74_000, 59_400),         # App. IV
    ("3457", "Peg Leg Ring", "ring_bending"): (1.34, 69_000, 51_400),       # App. IV
    ("3457", "Peg Leg Cone", "cone_tension"): (1.43, 69_000, 48_000),       # App. IV
    ("3457", "Parallelogram Post", "combined"): (1.26, 69_000, 54_400),     # App. IV
    ("3457", "Peg Leg Energy Absorber Rod", "tension"): (1.21, 69_000, 57_000),  # App. IV
    # App. IV, configs 3-5, 7, Peg Leg Absorber Cap: sigma_max printed 55,200, then f = 69,000/55,000 = 1.25 (either
    # gives 1.25)
    ("3457", "Peg Leg Absorber Cap", "plate_annular_inner_supported_uniform_pressure"): (1.25, 69_000, 55_200),
    ("3457", "Parallelogram Absorber Rods", "tension"): (1.21, 69_000, 57_000),  # App. IV
    ("3457", "Parallelogram Absorber Caps", "plate_supported_eccentric_and_distributed"):
        (4.94, 34_500, 6_975),                                              # App. IV, configs 3-5, 7, Parallelogram
                                                                            # Absorber Caps: tau_max 6,975
    # Articulated leg, configurations 6 and 8
    ("68", "Upper Truss", "compression"): (1.23, 74_000, 60_400),           # App. IV
    ("68", "Lower Truss", "compression"): (1.24, 74_000, 59_500),           # App. IV
    ("68", "Peg Leg Strut", "compression"): (1.20, 74_000, 61_600),         # App. IV
    ("68", "Peg Leg Ring", "ring_bending"): (1.34, 69_000, 51_300),         # App. IV
    ("68", "Peg Leg Cone", "cone_tension"): (1.43, 69_000, 48_000),         # App. IV "Same as 3, 4, 5 and 7"
    ("68", "Parallelogram Post", "combined"): (1.21, 69_000, 57_100),       # App. IV
    ("68", "Peg Leg Energy Absorber Rod", "tension"): (1.21, 69_000, 57_000),   # App. IV, configs 6, 8, Peg Leg
                                                                                # Absorber Rods "Same as ..."
    # App. IV, configs 6, 8, Peg Leg Absorber Cap "Same"
    ("68", "Peg Leg Absorber Cap", "plate_annular_inner_supported_uniform_pressure"): (1.25, 69_000, 55_200),
    ("68", "Parallelogram Absorber Rods", "tension"): (1.21, 69_000, 57_000),   # App. IV
    ("68", "Parallelogram Absorber Caps", "plate_supported_eccentric_and_distributed"):
        (3.84, 34_500, 8_999),                                              # App. IV, configs 6, 8, Parallelogram
                                                                            # Absorber Caps: tau_max 8,999
    # Articulated leg, configuration 9
    ("9", "Upper Truss", "compression"): (1.21, 74_000, 61_200),            # App. IV
    ("9", "Lower Truss", "compression"): (1.25, 74_000, 59_300),            # App. IV
    ("9", "Peg Leg Strut", "compression"): (1.20, 74_000, 62_000),          # App. IV
    ("9", "Peg Leg Ring", "ring_bending"): (1.20, 69_000, 57_500),          # App. IV (I used as 0.307 in^4)
    ("9", "Peg Leg Cone", "cone_tension"): (1.20, 69_000, 57_500),          # App. IV
    ("9", "Parallelogram Post", "combined"): (1.21, 69_000, 56_900),        # App. IV
    ("9", "Peg Leg Energy Absorber Rod", "tension"): (1.20, 69_000, 57_300),    # App. IV
    ("9", "Peg Leg Absorber Cap", "plate_annular_inner_supported_uniform_pressure"): (1.46, 69_000, 47_203),  # l.4752
    ("9", "Parallelogram Absorber Rods", "tension"): (1.20, 69_000, 57_200),    # App. IV
    ("9", "Parallelogram Absorber Caps", "plate_supported_eccentric_and_distributed"):
        (10.23, 34_500, 3_372),                                             # App. IV, config 9, Parallelogram Absorber
                                                                            # Caps: tau_max 3,372
}

# Stresses printed without a design factor: (configuration, item, kind) -> printed stress psi.
PRINTED_STRESSES = {
    ("012", "Lower Leg Tube", "bearing"): 2_110,        # App. IV: (261 + 6070)/3.00, "no problem"
    ("3457", "Peg Leg Strut", "compression"): 60_400,   # App. IV: 50,800/0.841 (f not printed)
}

# ------------------------------------------------------------------ App. IV critical buckling values
# Informational: (configuration, item, kind) -> (printed value, unit, the report's conclusion).
CRITICAL = {
    ("012", "Lower Leg Tube", "column_buckling"): (167_000, "lb", "45 times the column loading"),   # App. IV
    ("012", "Lower Leg Tube", "local_buckling"): (198_000, "psi", "over three times the stress"),   # App. IV
    ("3457", "Upper Truss", "column_buckling"): (12_000_000, "psi", "two hundred times"),           # App. IV
    ("3457", "Lower Truss", "column_buckling"): (119_500, "psi", "twice the column stress"),        # App. IV
    ("3457", "Peg Leg Strut", "column_buckling"): (585_000, "psi", "over nine times"),              # App. IV
    ("9", "Upper Truss", "column_buckling"): (126_000, "psi", "not a concern"),                     # App. IV
}

# ------------------------------------------------------------------ App. V weight tables
# Rows as printed (strings keep the printed digits), per leg: a row includes the item count
# ("Parallelogram Absorber Rods" = 6 rods, "Caps" = 2, "Rotational Honeycomb (4)" = 4 pads).
# total_4 = four legs; percent = total_4 / capsule weight.
TABLES = {
    "012": {  # Table 23
        "table": 23,
        "rows": {
            "Lower Leg": "0.600",                  # App. V: 0.074 pi (2.95)(0.05)(17.5)
            "Upper Leg": "0.586",                  # App. V: 0.074 pi (3.05)(0.05)(16.5)
            "Lower Plate": "0.231",                # App. V: 0.10 (0.785)(2.90)^2 (0.35)
            "Upper Plate": "0.247",                # App. V: 0.10 (0.785)(3.00)^2 (0.35)
            "Lower Cap": "0.330",                  # App. V: 0.275 + 20 % (0.055)
            "Upper Cap": "0.407",                  # App. V: 0.339 + 20 % (0.068)
            "Swivel": "0.145",                     # App. V: 0.283 (1.20)(0.5)(0.5) + 2 x 0.03
            "Axial Honeycomb": "0.123",            # App. V: 0.0133 (0.785)(1.074)^2 (10.25)
            "Rotational Honeycomb (4)": "0.097",   # App. V, telescoping leg, Rotational Absorber: 0.0133 (0.602)^2
                                                   # (5.0) = 0.0241 each
        },
        "total_each": "2.766", "total_4": "11.064", "percent": "3.69", "capsule_lb": 300,  # Table 23
    },
    "3457": {  # Table 24
        "table": 24,
        "rows": {
            "Upper Truss": "4.80",                 # App. V: (0.074/0.283)(4)(0.566/0.0984)(0.82)
            "Lower Truss": "6.55",                 # App. V: (0.074/0.283)(4)(0.329/0.065)(1.27)
            "Peg Leg Strut": "4.83",               # App. V: 0.4 (0.074/0.283)(4)(0.841/0.078)(1.10)
            "Peg Leg Ring": "8.02",                # App. V: 0.4 (1)(1.14)(16)(1.10)
            "Peg Leg Cone": "3.52",                # App. V: 0.1 (1)(2)(16)(1.1)
            "Remainder of Peg Leg": "7.04",        # App. V: 0.1 (1)(4)(16)(1.10)
            "Parallelogram Post": "24.80",         # App. V: 0.75 (1)(1)(16)(2.07) = 24.8
            "Remainder of Post": "13.50",          # App. V: 0.10 (1)(4)(16)(2.07) = 13.5
            "Peg Leg Energy Absorber Rod and Link": "5.11",  # App. V: 0.15 (0.10/0.283)(4)(0.525/0.045)(2.07)
            "Peg Leg Absorber Cap": "0.63",        # App. V: 0.10 (0.785)[3.14^2 - 0.818^2](0.88) = 0.634
            "Parallelogram Absorber Rods": "3.02",  # App. V: 0.10 (0.21)(24) = 0.503 each, 6 per leg
            "Parallelogram Absorber Caps": "1.00",  # App. V: 0.10 (0.785)[3.45^2 - 6 (0.52)^2](0.62) = 0.500 each, 2
            "Parallelogram Absorber Honeycomb": "1.68",  # App. V: (23/1728)(8.7)(14.5)
            "Peg Leg Absorber Honeycomb": "0.58",  # App. V: (23/1728)(7.2)(6)
        },
        "total_each": "85.08", "total_4": "340.03", "percent": "11.3", "capsule_lb": 3000,  # Table 24
    },
    "68": {  # Table 25
        "table": 25,
        "rows": {
            "Upper Truss": "7.20",                 # App. V: (0.074/0.283)(4)(0.840/0.0984)(0.82)
            "Lower Truss": "8.10",                 # App. V: (0.074/0.283)(4)(0.406/0.065)(1.27)
            "Peg Leg Strut": "6.09",               # App. V: (0.4)(0.074/0.283)(4)(1.04/0.078)(1.10)
            "Peg Leg Ring": "10.10",               # App. V: 0.4 (1)(1.44)(16)(1.10)
            "Peg Leg Cone": "3.52",                # App. V: same as 3, 4, 5 and 7
            "Remainder of Peg Leg": "8.87",        # App. V: 0.10 (1)(5.05)(16)(1.10)
            "Parallelogram Post": "31.20",         # App. V: 0.75 (1)(0.100/0.083)(16)(2.07)
            "Remainder of Post": "16.00",          # App. V: 0.10 (1)(0.100/0.083)(4)(16)(2.07)
            "Peg Leg Energy Absorber Rod and Link": "5.11",  # App. V: same as 3, 4, 5 and 7
            "Peg Leg Absorber Cap": "0.63",        # App. V: same, W = 0.634
            "Parallelogram Absorber Rods": "6.06",  # App. V: 0.10 (0.42)(24) = 1.01 each, 6 per leg
            "Parallelogram Absorber Caps": "2.98",  # App. V: 0.10 (0.785)[4.89^2 - 6 (0.74)^2](0.92) = 1.49 each, 2
            "Parallelogram Absorber Honeycomb": "3.36",  # App. V: (23/1728)(17.4)(14.5)
            # App. V, configs 6, 8, Peg Leg Absorber Honeycomb: "Same as configurations 3, 4, 5 and 7. W = 0.634 lb"
            # (that item is 0.58 lb; 0.634 is the absorber cap's weight). Table 25 uses 0.63 and its total 109.85
            # includes it.
            "Peg Leg Absorber Honeycomb": "0.63",
        },
        "total_each": "109.85", "total_4": "437.4", "percent": "14.8", "capsule_lb": 3000,  # Table 25
    },
    "9": {  # Table 26
        "table": 26,
        "rows": {
            "Upper Truss": "0.399",                # App. V: (0.074/0.283)(1.825)(0.1035/0.0984)(0.82)
            "Lower Truss": "0.568",                # App. V: (0.074/0.283)(1.825)(0.0627/0.065)(1.27)
            "Peg Leg Strut": "0.413",              # App. V: 0.4 (0.074/0.283)(1.825)(0.157/0.078)(1.1)
            "Peg Leg Ring": "0.634",               # App. V: 0.4 (1)(0.432)(1.825)^2 (1.10)
            "Peg Leg Cone": "0.300",               # App. V: 0.1 (1)(0.81)(1.825)^2 (1.1) = 0.30
            "Remainder of Peg Leg": "0.669",       # App. V: 0.1 (1)(1.825)(1.825)^2 (1.10)
            "Parallelogram Post": "2.140",         # App. V: 0.75 (1)(0.0344/0.083)(1.825)^2 (2.07) = 2.14
            "Remainder of Post": "1.270",          # App. V: 0.10 (1)(1.825)(1.825)^2 (2.07) = 1.27
            "Peg Leg Energy Absorber Rod and Link": "0.455",  # App. V: 0.15 (0.10/0.283)(1.825)(0.102/0.045)(2.07)
            "Peg Leg Absorber Cap": "0.035",       # App. V: 0.10 (0.785)[1.76^2 - 1.138^2](0.25)
            "Parallelogram Absorber Rods": "0.258",  # App. V: 0.10 (0.039)(11.0) = 0.043 each, 6 per leg
            "Parallelogram Absorber Caps": "0.144",  # App. V: 0.1 (0.785)[1.48^2 - 6 (0.23)^2](0.43) = 0.072 each, 2
            "Parallelogram Absorber Honeycomb": "0.140",  # App. V: (23/1728)(1.61)(6.65) = 0.14
            "Peg Leg Absorber Honeycomb": "0.050",  # App. V: (23/1728)(1.41)(2.74) = 0.05
        },
        "total_each": "7.475", "total_4": "29.90", "percent": "10.0", "capsule_lb": 300,  # Table 26
    },
}
