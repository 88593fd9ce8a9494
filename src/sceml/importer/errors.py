"""The one error type of `sceml import`: input that cannot be used, with file and line."""

from __future__ import annotations

from ..errors import SceMLError


class XoscImportError(SceMLError):
    """An OpenSCENARIO file cannot be imported (malformed, wrong version, dangling or circular
    reference, missing catalog); nothing is written. Exit code 2: the input is unusable."""

    exit_code = 2
