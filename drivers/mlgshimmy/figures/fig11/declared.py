"""What make, make help, make submit and the report know of this figure
(shared.jobs.catalogue reads it as text: literals only)."""
DECLARED = {
    "fig11": {
        "help": "Fig. 11: (V, F*) plane with freeplay, lift-off edge; -j2: 6 min",
        "time": "11 min",
        "regress": True,
        "parts": True,
        "needs": ["simulator"],
        "report": ("The (V, F*) plane with freeplay: Hopf, fold and pitchfork curves and the "
                   "regions of low- and high-frequency shimmy, bistability and off-centre yaw "
                   "(IV.B, IV.C)."),
    },
}
