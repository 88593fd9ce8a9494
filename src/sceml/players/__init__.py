"""Real players (esmini first): what each maneuver means to them, and checking their runs.

- `meaning`: one definition of each maneuver's start, behaviour and finish, read by the export,
  the preview, the run checker and the validation rules;
- `check.check_player_run(scenario, log, trace)`: whether a player's run kept the scenario's
  meaning (`sceml check-run`), a `checker.RunReport`;
- `esmini`: esmini's log and CSV formats, and running esmini;
- `compare`: a preview run beside a player's run of the same scenario.
"""
