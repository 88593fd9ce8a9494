"""`python -m sceml.cli`: the same as the `sceml` command."""

from . import main

main()
