"""The import report: what was mapped to which SceML kind, kept opaque (with its line), guessed,
or not represented, so that nothing is lost silently."""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field

#: The kinds of entries, in the order the text report lists them.
SECTIONS = ("mapped", "opaque", "guessed", "not represented")


@dataclass(frozen=True)
class Entry:
    """One thing the import did with one element of the file."""

    section: str
    message: str
    file: str | None = None
    line: int | None = None
    node: str | None = None


@dataclass
class ImportReport:
    """Everything `sceml import --report` prints; `entries` in the order they were made."""

    file: str
    version: str = ""
    #: The lowest OpenSCENARIO version that can say everything read, where it is above
    #: `version` (esmini reads a 1.3 trailer in a 1.1 file; its export needs 1.3); "" when not.
    needs_version: str = ""
    entries: list[Entry] = field(default_factory=list)
    parameters: dict[str, str] = field(default_factory=dict)
    catalog_entries: list[str] = field(default_factory=list)
    #: The ParameterValueDistribution read with the file, if any.
    distribution: str | None = None
    #: What became logical: parameter path -> `$parameter: distribution`.
    logical: dict[str, str] = field(default_factory=dict)

    def add(
        self,
        section: str,
        message: str,
        where: tuple[str, int | None] | None = None,
        node: str | None = None,
    ) -> None:
        """Record one entry of `section` (mapped, opaque, guessed, not represented)."""
        assert section in SECTIONS, section
        file, line = where if where is not None else (None, None)
        self.entries.append(Entry(section, message, file, line, node))

    def section(self, name: str) -> list[Entry]:
        """The entries of one section."""
        return [entry for entry in self.entries if entry.section == name]

    def counts(self) -> Counter[str]:
        """How many entries each section has."""
        return Counter(entry.section for entry in self.entries)

    def text(self) -> str:
        """The report as text: a summary line, then each section with one line per entry."""
        counts = self.counts()
        lines = [
            f"{self.file}: OpenSCENARIO {self.version}; "
            + ", ".join(f"{counts[name]} {name}" for name in SECTIONS)
        ]
        if self.parameters:
            used = ", ".join(f"{k}={v}" for k, v in sorted(self.parameters.items()))
            lines.append(f"parameters resolved: {used}")
        if self.distribution is not None:
            lines.append(
                f"distribution {self.distribution}: {len(self.logical)} places logical"
                + "".join(f"\n  {path} = {what}" for path, what in self.logical.items())
            )
        if self.catalog_entries:
            lines.append(f"catalog entries used: {', '.join(sorted(set(self.catalog_entries)))}")
        for name in SECTIONS:
            entries = self.section(name)
            if entries:
                lines.append(f"{name} ({len(entries)}):")
                lines.extend(f"  {_line(entry, self.file)}" for entry in entries)
        return "\n".join(lines) + "\n"


def _line(entry: Entry, primary: str) -> str:
    where = ""
    if entry.line:
        where = (
            f"line {entry.line}: "
            if entry.file in (None, primary)
            else f"{entry.file}:{entry.line}: "
        )
    return f"{where}{entry.message}"
