"""Printed results of AFFDL-TR-66-33 App. IV (stress design factors) and App. V (weights, Tables 23-26).

Transcribed from the report text, /work/shared/reference/000_9b9e1976ecb8d0f1.txt ("l." = line of that
file), as printed, misprints included. Units as printed: lb, lb/in^2 (psi), in. Configuration ids are those
of the example configs: "012" telescoping, "3457", "68" and "9" articulated.
"""

# ------------------------------------------------------------------ App. IV design factors
# (configuration, item name, check kind) -> (printed f, printed allowable psi, printed stress psi).
# The allowable is the yield (or yield / 2 where the check is a maximum-shear one); the stress is the one f
# is computed from. pin_shear is on loads: allowable = bolt capacity (lb), stress = resultant load (lb).
DESIGN_FACTORS = {
    # Telescoping leg, configurations 0, 1, 2
    ("012", "Lower Leg Tube", "combined"): (1.26, 74_000, 58_600),          # l. 3918: 74,000/58,600
    ("012", "Lower Leg Cap", "plate_fixed_center_load"): (1.25, 34_500, 27_500),    # l. 3940: (69,000/2)/27,500
    ("012", "Upper and Lower Plates", "plate_supported_center_load"): (1.24, 34_500, 28_100),  # l. 3966
    ("012", "Upper Leg Tube", "combined"): (1.42, 74_000, 52_020),          # l. 3998: 74,000/52,020
    ("012", "Double Pin Swivel", "pin_shear"): (2.37, 9_300, 3_930),        # l. 4018: 9,300 lb / 3,930 lb
    ("012", "Double Pin Swivel", "combined"): (2.20, 180_000, 81_600),      # l. 4042: 180,000/81,600
    ("012", "Upper Leg Cap", "plate_fixed_center_moment_and_load"): (1.53, 34_500, 22_490),  # l. 4086
    ("012", "Upper Cap Lugs", "bearing"): (1.75, 69_000, 39_400),           # l. 4102: 69,000/39,400
    ("012", "Upper Cap Lugs", "combined"): (1.42, 69_000, 48_800),          # l. 4126: 69,000/48,800
    # Articulated leg, configurations 3, 4, 5 and 7
    ("3457", "Upper Truss", "compression"): (1.24, 74_000, 59_700),         # l. 4164
    ("3457", "Lower Truss", "compression"): (1.25, 74_000, 59_400),         # l. 4194
    ("3457", "Peg Leg Ring", "ring_bending"): (1.34, 69_000, 51_400),       # l. 4244
    ("3457", "Peg Leg Cone", "cone_tension"): (1.43, 69_000, 48_000),       # l. 4264
    ("3457", "Parallelogram Post", "combined"): (1.26, 69_000, 54_400),     # l. 4298
    ("3457", "Peg Leg Energy Absorber Rod", "tension"): (1.21, 69_000, 57_000),  # l. 4316
    # l. 4334-4338: sigma_max printed 55,200, then f = 69,000/55,000 = 1.25 (either gives 1.25)
    ("3457", "Peg Leg Absorber Cap", "plate_annular_inner_supported_uniform_pressure"): (1.25, 69_000, 55_200),
    ("3457", "Parallelogram Absorber Rods", "tension"): (1.21, 69_000, 57_000),  # l. 4358
    ("3457", "Parallelogram Absorber Caps", "plate_supported_eccentric_and_distributed"):
        (4.94, 34_500, 6_975),                                              # l. 4390: tau_max 6,975
    # Articulated leg, configurations 6 and 8
    ("68", "Upper Truss", "compression"): (1.23, 74_000, 60_400),           # l. 4410
    ("68", "Lower Truss", "compression"): (1.24, 74_000, 59_500),           # l. 4432
    ("68", "Peg Leg Strut", "compression"): (1.20, 74_000, 61_600),         # l. 4450
    ("68", "Peg Leg Ring", "ring_bending"): (1.34, 69_000, 51_300),         # l. 4474
    ("68", "Peg Leg Cone", "cone_tension"): (1.43, 69_000, 48_000),         # l. 4478 "Same as 3, 4, 5 and 7"
    ("68", "Parallelogram Post", "combined"): (1.21, 69_000, 57_100),       # l. 4512
    ("68", "Peg Leg Energy Absorber Rod", "tension"): (1.21, 69_000, 57_000),   # l. 4514-4516 "Same as ..."
    # l. 4518-4520 "Same"
    ("68", "Peg Leg Absorber Cap", "plate_annular_inner_supported_uniform_pressure"): (1.25, 69_000, 55_200),
    ("68", "Parallelogram Absorber Rods", "tension"): (1.21, 69_000, 57_000),   # l. 4538
    ("68", "Parallelogram Absorber Caps", "plate_supported_eccentric_and_distributed"):
        (3.84, 34_500, 8_999),                                              # l. 4568: tau_max 8,999
    # Articulated leg, configuration 9
    ("9", "Upper Truss", "compression"): (1.21, 74_000, 61_200),            # l. 4600
    ("9", "Lower Truss", "compression"): (1.25, 74_000, 59_300),            # l. 4620
    ("9", "Peg Leg Strut", "compression"): (1.20, 74_000, 62_000),          # l. 4638
    ("9", "Peg Leg Ring", "ring_bending"): (1.20, 69_000, 57_500),          # l. 4666 (I used as 0.307 in^4)
    ("9", "Peg Leg Cone", "cone_tension"): (1.20, 69_000, 57_500),          # l. 4682
    ("9", "Parallelogram Post", "combined"): (1.21, 69_000, 56_900),        # l. 4714
    ("9", "Peg Leg Energy Absorber Rod", "tension"): (1.20, 69_000, 57_300),    # l. 4732
    ("9", "Peg Leg Absorber Cap", "plate_annular_inner_supported_uniform_pressure"): (1.46, 69_000, 47_203),  # l.4752
    ("9", "Parallelogram Absorber Rods", "tension"): (1.20, 69_000, 57_200),    # l. 4772
    ("9", "Parallelogram Absorber Caps", "plate_supported_eccentric_and_distributed"):
        (10.23, 34_500, 3_372),                                             # l. 4806: tau_max 3,372
}

# Stresses printed without a design factor: (configuration, item, kind) -> printed stress psi.
PRINTED_STRESSES = {
    ("012", "Lower Leg Tube", "bearing"): 2_110,        # l. 3908: (261 + 6070)/3.00, "no problem"
    ("3457", "Peg Leg Strut", "compression"): 60_400,   # l. 4210: 50,800/0.841 (f not printed)
}

# ------------------------------------------------------------------ App. IV critical buckling values
# Informational: (configuration, item, kind) -> (printed value, unit, the report's conclusion).
CRITICAL = {
    ("012", "Lower Leg Tube", "column_buckling"): (167_000, "lb", "45 times the column loading"),   # l. 3890-3892
    ("012", "Lower Leg Tube", "local_buckling"): (198_000, "psi", "over three times the stress"),   # l. 3902-3904
    ("3457", "Upper Truss", "column_buckling"): (12_000_000, "psi", "two hundred times"),           # l. 4158-4160
    ("3457", "Lower Truss", "column_buckling"): (119_500, "psi", "twice the column stress"),        # l. 4188-4190
    ("3457", "Peg Leg Strut", "column_buckling"): (585_000, "psi", "over nine times"),              # l. 4216-4218
    ("9", "Upper Truss", "column_buckling"): (126_000, "psi", "not a concern"),                     # l. 4594-4596
}

# ------------------------------------------------------------------ App. V weight tables
# Rows as printed (strings keep the printed digits), per leg: a row includes the item count
# ("Parallelogram Absorber Rods" = 6 rods, "Caps" = 2, "Rotational Honeycomb (4)" = 4 pads).
# total_4 = four legs; percent = total_4 / capsule weight.
TABLES = {
    "012": {  # Table 23, l. 4882-4899
        "table": 23,
        "rows": {
            "Lower Leg": "0.600",                  # l. 4816: 0.074 pi (2.95)(0.05)(17.5)
            "Upper Leg": "0.586",                  # l. 4820: 0.074 pi (3.05)(0.05)(16.5)
            "Lower Plate": "0.231",                # l. 4824: 0.10 (0.785)(2.90)^2 (0.35)
            "Upper Plate": "0.247",                # l. 4828: 0.10 (0.785)(3.00)^2 (0.35)
            "Lower Cap": "0.330",                  # l. 4832-4836: 0.275 + 20 % (0.055)
            "Upper Cap": "0.407",                  # l. 4840-4844: 0.339 + 20 % (0.068)
            "Swivel": "0.145",                     # l. 4858-4862: 0.283 (1.20)(0.5)(0.5) + 2 x 0.03
            "Axial Honeycomb": "0.123",            # l. 4850: 0.0133 (0.785)(1.074)^2 (10.25)
            "Rotational Honeycomb (4)": "0.097",   # l. 4854: 0.0133 (0.602)^2 (5.0) = 0.0241 each
        },
        "total_each": "2.766", "total_4": "11.064", "percent": "3.69", "capsule_lb": 300,  # l. 4896-4899
    },
    "3457": {  # Table 24, l. 4993-5015
        "table": 24,
        "rows": {
            "Upper Truss": "4.80",                 # l. 4921: (0.074/0.283)(4)(0.566/0.0984)(0.82)
            "Lower Truss": "6.55",                 # l. 4926: (0.074/0.283)(4)(0.329/0.065)(1.27)
            "Peg Leg Strut": "4.83",               # l. 4931: 0.4 (0.074/0.283)(4)(0.841/0.078)(1.10)
            "Peg Leg Ring": "8.02",                # l. 4937: 0.4 (1)(1.14)(16)(1.10)
            "Peg Leg Cone": "3.52",                # l. 4989: 0.1 (1)(2)(16)(1.1)
            "Remainder of Peg Leg": "7.04",        # l. 4943: 0.1 (1)(4)(16)(1.10)
            "Parallelogram Post": "24.80",         # l. 4949: 0.75 (1)(1)(16)(2.07) = 24.8
            "Remainder of Post": "13.50",          # l. 4955: 0.10 (1)(4)(16)(2.07) = 13.5
            "Peg Leg Energy Absorber Rod and Link": "5.11",  # l. 4961: 0.15 (0.10/0.283)(4)(0.525/0.045)(2.07)
            "Peg Leg Absorber Cap": "0.63",        # l. 4965: 0.10 (0.785)[3.14^2 - 0.818^2](0.88) = 0.634
            "Parallelogram Absorber Rods": "3.02",  # l. 4969: 0.10 (0.21)(24) = 0.503 each, 6 per leg
            "Parallelogram Absorber Caps": "1.00",  # l. 4975: 0.10 (0.785)[3.45^2 - 6 (0.52)^2](0.62) = 0.500 each, 2
            "Parallelogram Absorber Honeycomb": "1.68",  # l. 4979: (23/1728)(8.7)(14.5)
            "Peg Leg Absorber Honeycomb": "0.58",  # l. 4983: (23/1728)(7.2)(6)
        },
        "total_each": "85.08", "total_4": "340.03", "percent": "11.3", "capsule_lb": 3000,  # l. 5012-5015
    },
    "68": {  # Table 25, l. 5102-5124
        "table": 25,
        "rows": {
            "Upper Truss": "7.20",                 # l. 5021: (0.074/0.283)(4)(0.840/0.0984)(0.82)
            "Lower Truss": "8.10",                 # l. 5025: (0.074/0.283)(4)(0.406/0.065)(1.27)
            "Peg Leg Strut": "6.09",               # l. 5029: (0.4)(0.074/0.283)(4)(1.04/0.078)(1.10)
            "Peg Leg Ring": "10.10",               # l. 5033: 0.4 (1)(1.44)(16)(1.10)
            "Peg Leg Cone": "3.52",                # l. 5035-5039: same as 3, 4, 5 and 7
            "Remainder of Peg Leg": "8.87",        # l. 5046: 0.10 (1)(5.05)(16)(1.10)
            "Parallelogram Post": "31.20",         # l. 5051: 0.75 (1)(0.100/0.083)(16)(2.07)
            "Remainder of Post": "16.00",          # l. 5056: 0.10 (1)(0.100/0.083)(4)(16)(2.07)
            "Peg Leg Energy Absorber Rod and Link": "5.11",  # l. 5058-5062: same as 3, 4, 5 and 7
            "Peg Leg Absorber Cap": "0.63",        # l. 5064-5068: same, W = 0.634
            "Parallelogram Absorber Rods": "6.06",  # l. 5072: 0.10 (0.42)(24) = 1.01 each, 6 per leg
            "Parallelogram Absorber Caps": "2.98",  # l. 5080: 0.10 (0.785)[4.89^2 - 6 (0.74)^2](0.92) = 1.49 each, 2
            "Parallelogram Absorber Honeycomb": "3.36",  # l. 5084: (23/1728)(17.4)(14.5)
            # l. 5086-5090: "Same as configurations 3, 4, 5 and 7. W = 0.634 lb" (that item is 0.58 lb;
            # 0.634 is the absorber cap's weight). Table 25 uses 0.63 and its total 109.85 includes it.
            "Peg Leg Absorber Honeycomb": "0.63",
        },
        "total_each": "109.85", "total_4": "437.4", "percent": "14.8", "capsule_lb": 3000,  # l. 5121-5124
    },
    "9": {  # Table 26, l. 5187-5210
        "table": 26,
        "rows": {
            "Upper Truss": "0.399",                # l. 5096: (0.074/0.283)(1.825)(0.1035/0.0984)(0.82)
            "Lower Truss": "0.568",                # l. 5100: (0.074/0.283)(1.825)(0.0627/0.065)(1.27)
            "Peg Leg Strut": "0.413",              # l. 5131: 0.4 (0.074/0.283)(1.825)(0.157/0.078)(1.1)
            "Peg Leg Ring": "0.634",               # l. 5136: 0.4 (1)(0.432)(1.825)^2 (1.10)
            "Peg Leg Cone": "0.300",               # l. 5141: 0.1 (1)(0.81)(1.825)^2 (1.1) = 0.30
            "Remainder of Peg Leg": "0.669",       # l. 5146: 0.1 (1)(1.825)(1.825)^2 (1.10)
            "Parallelogram Post": "2.140",         # l. 5151: 0.75 (1)(0.0344/0.083)(1.825)^2 (2.07) = 2.14
            "Remainder of Post": "1.270",          # l. 5160: 0.10 (1)(1.825)(1.825)^2 (2.07) = 1.27
            "Peg Leg Energy Absorber Rod and Link": "0.455",  # l. 5165: 0.15 (0.10/0.283)(1.825)(0.102/0.045)(2.07)
            "Peg Leg Absorber Cap": "0.035",       # l. 5169: 0.10 (0.785)[1.76^2 - 1.138^2](0.25)
            "Parallelogram Absorber Rods": "0.258",  # l. 5173: 0.10 (0.039)(11.0) = 0.043 each, 6 per leg
            "Parallelogram Absorber Caps": "0.144",  # l. 5177: 0.1 (0.785)[1.48^2 - 6 (0.23)^2](0.43) = 0.072 each, 2
            "Parallelogram Absorber Honeycomb": "0.140",  # l. 5181: (23/1728)(1.61)(6.65) = 0.14
            "Peg Leg Absorber Honeycomb": "0.050",  # l. 5185: (23/1728)(1.41)(2.74) = 0.05
        },
        "total_each": "7.475", "total_4": "29.90", "percent": "10.0", "capsule_lb": 300,  # l. 5207-5210
    },
}
