"""OpenSCENARIO facts and file checking, below validation and export: both read it.

The versions and profiles SceML writes and what each can express (`support`, `profiles`).
"""

#: The step of a player's clock, in seconds: esmini's `--fixed_timestep` as SceML runs it, and the
#: preview's, the recorder's and the search's default, so that they count time alike. A flow out
#: of the root costs no step (`xosc.flows.flow_steps`): the export writes "the root has finished"
#: as `SimulationTime >= 0`, which holds at t = 0. An original's `SimulationTime > v` first holds
#: one step after v (esmini 3.6: `> 0` at 0.05 s, `> 2` at 2.05 s; `>= 2` at 2.00 s), so the
#: import reads it as a wait of v plus this step, and `>= v` as a wait of v. Kept here, where
#: importing it costs nothing.
PLAYER_STEP = 0.05
