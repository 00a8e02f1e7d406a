"""What make, make help, make submit and the report know of this study
(shared.jobs.catalogue reads it as text: literals only)."""
DECLARED = {
    "atlas": {
        "help": "attractor atlas by simulation over (V, F*); -j2: 9 min",
        "time": "17 min",
        "grid": "ATLAS_ARGS",
        "report": {
            "command": "make -j2 atlas",
            "text": ("The attractor atlas: what a time simulation settles on over (V, F*), "
                     "y_fp = 1 mm, eps = 0.1 mm, and its comparison with Fig. 11."),
            "tables": ["atlas/summary.txt"],
            "figures": ["figures/atlas.png", "figures/atlas_fig11.png"],
        },
    },
}
