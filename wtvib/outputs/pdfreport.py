"""PDF audit reports (reportlab): a document to hand to a certification reviewer.

Built from the report's JSON (``to_dict()``) and the Campbell PNGs (150 dpi), so a batch
can assemble one document from the results of its worker processes. Tables are real text.
Its document id is fixed (reportlab's invariant mode) and its creation date the real one,
or ``SOURCE_DATE_EPOCH`` where set: with that, the same inputs give the same bytes. An
outline (bookmarks) leads to each turbine and each of its sections.
"""

import io
import os
import re
import time
from collections.abc import Mapping, Sequence
from typing import Any

from .. import __version__
from ..document import (
    CheckDoc,
    ModeDoc,
    ReportDoc,
    RuleDoc,
    RuleSettingsDoc,
    UncertaintyDoc,
)
from . import png, words

STATUS_HEX = {
    "pass": "#2e7d32",
    "info": "#1565c0",
    "warn": "#ef6c00",
    "fail": "#c62828",
    "input-error": "#6a1b9a",
    "internal-error": "#4a148c",
}
SUBSYSTEM_NAMES = {
    "tower": "Tower",
    "blade": "Blades",
    "drivetrain": "Drive train",
    "yaw": "Yaw system",
    "rotor": "Rotor on the tower head (periodic coefficients, Floquet)",
    "system": "Whole turbine: coupled rotor–tower model (Hau §7.6)",
    "aerodynamics": "In operation: aerodynamic damping of every mode (Hau §7.5.1)",
    "polynomials": "ElastoDyn's mode-shape polynomials: the deck's own against the computed",
}
DIAGRAM_FOR = {
    "tower": ("campbell",),
    "blade": ("campbell", "blade-flutter", "blade-stability", "blade-stall"),
    "drivetrain": ("campbell-drivetrain", "drivetrain-modes", "drivetrain-power"),
    "yaw": ("campbell-yaw",),
    "rotor": ("floquet",),
    "system": ("campbell-system", "standstill", "system-energy"),
    "aerodynamics": ("damping",),
    "polynomials": ("shapes",),
}


def once_wrapped(paragraph: type) -> type:
    """reportlab's Paragraph, breaking its lines once per width: a table wraps every cell
    again at each split across pages — two thirds of a catalogue PDF's build went to
    breaking the same lines again (the same bytes, a test)."""

    class OnceWrapped(paragraph):  # type: ignore[misc]
        def wrap(self, width: float, height: float) -> tuple[float, float]:
            # (split() drops the broken lines where a paragraph moves on whole)
            if getattr(self, "_wrapped_at", None) != width or not hasattr(self, "blPara"):
                self._wrapped = super().wrap(width, height)
                self._wrapped_at = width
            return self._wrapped  # type: ignore[no-any-return]

    return OnceWrapped


class _Kit:
    """reportlab pieces and the house style, imported lazily (reportlab is slow to import)."""

    def __init__(self) -> None:
        from reportlab import rl_config

        rl_config.invariant = 1  # reproducible files: no dates, fixed document id
        rl_config.useA85 = 0  # binary streams: ASCII85 is pure Python (slow) and 25 % larger
        from reportlab.lib import colors
        from reportlab.lib.pagesizes import A4
        from reportlab.lib.styles import getSampleStyleSheet
        from reportlab.lib.units import mm
        from reportlab.platypus import (
            CondPageBreak,
            KeepTogether,
            PageBreak,
            Paragraph,
            SimpleDocTemplate,
            Spacer,
            Table,
            TableStyle,
        )

        self.colors, self.A4, self.mm = colors, A4, mm
        self.KeepTogether, self.PageBreak = KeepTogether, PageBreak
        self.CondPageBreak = CondPageBreak
        self.Paragraph, self.Spacer, self.Table, self.TableStyle = (
            once_wrapped(Paragraph),
            Spacer,
            Table,
            TableStyle,
        )
        self.SimpleDocTemplate = SimpleDocTemplate
        from .pdfpng import image

        self.image = image
        self.styles = getSampleStyleSheet()
        # a section heading is kept off the foot of a page by the room asked before it
        # (:meth:`heading`), not by keepWithNext, which moves the heading with the whole
        # table after it: a page-long table left the page before it half empty
        self.styles["Heading1"].keepWithNext = 1
        self.small = self.styles["BodyText"].clone("small", fontSize=8, leading=9.6)
        # a number is never broken inside (reportlab splits a word longer than its cell
        # by default: "1899.1" / "%"); its cell is made wide enough instead
        self.numbers = self.small.clone("numbers", splitLongWords=0)
        self.width = A4[0] - 36 * mm
        #: the tallest figure a page takes (its frame is 265 mm): a taller one (a legend of
        #: many rows makes the figure taller) is drawn narrower, never too large for a page
        self.tallest = 230 * mm

    def p(self, text: Any, style: str | None = None) -> Any:
        """A paragraph of plain text (escaped), at most :data:`MAX_TEXT` characters (a
        longer one is cut, and says how much is left out)."""
        text = str(text)
        if len(text) > MAX_TEXT:
            text = f"{text[:MAX_TEXT]}… ({len(text) - MAX_TEXT:,} characters more)"
        # a number keeps its unit on its line ("23.4 %", "0.891 Hz"), in prose too
        return self.raw(_UNIT_SPACE.sub("\\1&nbsp;", _esc(text)), style)

    def num(self, text: str) -> Any:
        """A cell of numbers: never broken inside a number, nor between a number and its
        unit ("6.54 m/s" stays on one line)."""
        return self.Paragraph(_UNIT_SPACE.sub("\\1&nbsp;", _esc(text)), self.numbers)

    def raw(self, markup: str, style: str | None = None) -> Any:
        """A paragraph of reportlab mini-markup."""
        return self.Paragraph(markup, self.styles[style] if style else self.small)

    def heading(self, text: str) -> list[Any]:
        """A section heading, on the next page where less than 50 mm is left on this one."""
        return [self.CondPageBreak(50 * self.mm), self.p(text, "Heading2")]

    def ident(self, name: str, fraction: float) -> Any:
        """A dotted id or field path in a column ``fraction`` of the text width wide: broken
        after a dot where it does not fit, never mid-word ("…mesh.st" / "age2")."""
        from reportlab.pdfbase.pdfmetrics import stringWidth

        from ..results import dotted_lines

        room = fraction * self.width - 12  # the cell's padding: 6 pt a side
        font, size = self.small.fontName, self.small.fontSize
        lines = dotted_lines(name, lambda line: stringWidth(line, font, size) <= room)
        return self.raw("<br/>".join(_esc(line) for line in lines))

    def status(self, s: str, mark: str = "") -> Any:
        label = s.upper().replace("-", " ") + mark
        return self.raw(f'<font color="{STATUS_HEX[s]}"><b>{label}</b></font>')

    def table(self, rows: list[list[Any]], widths: list[float]) -> Any:
        # splitInRow: a row taller than a page (a 4,000-character name, an 800-word note)
        # continues on the next page instead of failing the layout
        t = self.Table(rows, colWidths=[w * self.width for w in widths], repeatRows=1, splitInRow=1)
        t.setStyle(
            self.TableStyle(
                [
                    ("BACKGROUND", (0, 0), (-1, 0), self.colors.HexColor("#eceff1")),
                    ("GRID", (0, 0), (-1, -1), 0.25, self.colors.HexColor("#b0bec5")),
                    ("VALIGN", (0, 0), (-1, -1), "TOP"),
                ]
            )
        )
        return t

    def header(self, *names: str) -> list[Any]:
        return [self.raw(f"<b>{_esc(n)}</b>") for n in names]


#: A space between a number and its unit or per cent sign, to be a non-breaking one.
_UNIT_SPACE = re.compile(r"(\d) (?=[%a-zA-Zζ°/])")

#: The longest text one paragraph of the PDF shows (a page holds about 6,000 characters of
#: its small type): a longer name or note is cut there, saying so.
MAX_TEXT = 2000


def build(
    entries: Sequence[tuple[ReportDoc, dict[str, bytes]]],
    *,
    errors: Sequence[tuple[str, str, str]] = (),
    title: str = "wtvib vibration audit",
) -> bytes:
    """PDF bytes for one or many audited turbines (and the inputs that failed to load).

    Parameters
    ----------
    entries
        (report dict, {diagram suffix: PNG bytes}) per turbine.
    errors
        (file, one-line message) per input that could not be audited.
    """
    k = _Kit()
    story: list[Any] = [k.p(title, "Title")]
    names = ", ".join(r["turbine"]["name"] for r, _ in entries) or "—"
    story.append(k.p(f"Turbines: {names}", "BodyText"))
    story.append(
        k.p(
            f"Produced by wtvib {__version__}. Natural frequencies are checked against "
            "rotor and drive-train excitations after Hau, Wind Turbines, ch. 7; each "
            "check names its rule and source, and every annotated input its "
            "provenance.",
            "BodyText",
        )
    )
    story.append(k.Spacer(1, 4 * k.mm))
    rows = [k.header("turbine", "file", "tower class", "verdict", "worst check", "margin")]
    for r, _ in entries:
        worst = _worst(r["checks"])
        rows.append(
            [
                k.p(r["turbine"]["name"]),
                k.p(r["turbine"]["source_file"]),
                k.p(r["tower_class"] or "—"),
                k.status(r["verdict"], "*" if r["warnings"] else ""),
                k.ident(worst["id"], 0.24) if worst else k.p("—"),
                k.num(_pct(worst.get("margin")) if worst else ""),
            ]
        )
    for file, message, outcome in errors:
        rows.append([k.p("—"), k.p(file), k.p("—"), k.status(outcome), k.p(message), k.p("")])
    story.append(k.table(rows, [0.2, 0.28, 0.1, 0.1, 0.24, 0.08]))
    if any(r["warnings"] for r, _ in entries):  # a verdict that rests on an assumption
        story.append(k.p("* with warnings: see the turbine's own pages.", "BodyText"))
    for r, pngs in entries:
        story += [k.PageBreak(), *_turbine(k, r, pngs)]

    buf = io.BytesIO()
    doc = _outlined(k.SimpleDocTemplate)(
        buf,
        pagesize=k.A4,
        leftMargin=18 * k.mm,
        rightMargin=18 * k.mm,
        topMargin=16 * k.mm,
        bottomMargin=16 * k.mm,
        title=title,
        author="wtvib",
        creator=f"wtvib {__version__}",
        subject="Vibration audit after Hau, Wind Turbines, ch. 7",
    )
    doc.build(story, onFirstPage=_footer, onLaterPages=_footer, canvasmaker=_dated())
    return buf.getvalue()


def created() -> time.struct_time:
    """When the document is made (UTC): now, or ``SOURCE_DATE_EPOCH`` where it is set
    (reproducible builds: https://reproducible-builds.org/specs/source-date-epoch/)."""
    given = os.environ.get("SOURCE_DATE_EPOCH", "").strip()
    try:
        return time.gmtime(int(given)) if given else time.gmtime()
    except (ValueError, OverflowError, OSError):  # not a time: the present one
        return time.gmtime()


def _dated() -> type:
    """A canvas that writes the document's real creation date (:func:`created`) — reportlab's
    invariant mode, kept for its fixed document id, would write 2000-01-01."""
    from reportlab.pdfgen.canvas import Canvas

    stamp = time.strftime("D:%Y%m%d%H%M%S+00'00'", created())

    class Dated(Canvas):  # type: ignore[misc]
        def __init__(self, *args: Any, **kwargs: Any) -> None:
            super().__init__(*args, **kwargs)
            self._doc.setDateFormatter(lambda *_: stamp)

    return Dated


def _outlined(template: type) -> type:
    """The document template with an outline (bookmarks): each turbine (its Heading1) and,
    under it, each of its sections (Heading2)."""

    class Outlined(template):  # type: ignore[misc]
        _marks = 0

        def afterFlowable(self, flowable: Any) -> None:  # noqa: N802 (reportlab's hook)
            style = getattr(getattr(flowable, "style", None), "name", None)
            level = {"Heading1": 0, "Heading2": 1}.get(style or "")
            if level is None:
                return
            self._marks += 1
            key = f"mark{self._marks}"
            text = flowable.getPlainText()
            if level == 1 and text.startswith("Verdict:"):
                return  # the verdict line under the turbine's name is no section
            self.canv.bookmarkPage(key)
            self.canv.addOutlineEntry(text, key, level=level, closed=level == 0)

    return Outlined


def _turbine(k: _Kit, r: ReportDoc, pngs: dict[str, bytes]) -> list[Any]:
    """One turbine's pages: who it is and the verdict, its warnings, the summary of checks,
    a section a subsystem (modes, figures, checks), the uncertainty study, the inputs and
    the assumptions."""
    out = _identity(k, r) + _warnings(k, r) + _summary(k, r)
    drawn: set[str] = set()
    others = dict.fromkeys(
        c["subsystem"] for c in r["checks"] if c["subsystem"] not in SUBSYSTEM_NAMES
    )
    for sub, title in {**SUBSYSTEM_NAMES, **{o: f"Checks of {o}" for o in others}}.items():
        out += _subsystem(k, r, sub, title, pngs, drawn)
    if r.get("uncertainty"):
        out += _uncertainty(k, r["uncertainty"])
    out += _inputs(k, r)
    out += k.heading("Assumptions")
    out += [k.p(f"• {a}", "BodyText") for a in r["assumptions"]]
    return out


def _identity(k: _Kit, r: ReportDoc) -> list[Any]:
    """The turbine's name, verdict and identity table (source, rotor, operation, rule)."""
    t, op, rule = r["turbine"], r["operation"], r["rule"]
    out: list[Any] = [
        k.KeepTogether(
            [
                k.p(t["name"], "Heading1"),
                k.raw(
                    f'Verdict: <font color="{STATUS_HEX[r["verdict"]]}"><b>'
                    f"{r['verdict'].upper()}</b></font>",
                    "Heading2",
                ),
            ]
        )
    ]
    ident: list[list[Any]] = [
        ["source file", t["source_file"]],
        ["input SHA-256", r["produced_by"]["input"]["sha256"] or "—"],
        ["rotor", f"{words.counted(t['blades'], 'blade')}, {t['orientation']}, {t['hub']} hub"],
        [
            "operation",
            words.operation(op)
            + (
                f"; quick-pass bands {op['quick_pass_rpm'] or 'none'}"
                if not op.get("parked")
                else ""
            ),
        ],
        ["tower class", r["tower_class"] or "—"],
        [
            "margin rule",
            f"{rule['kind']}, m = {rule['margin']:.0%} "
            f"({rule['preset'] or 'custom'}): {rule['source']}",
        ],
    ]
    if r.get("damping") == "aeroelastic":  # a structural audit says so in its checks
        ident.append(["damping", "aeroelastic (aerodynamic + structural, at the operating points)"])
    given: Mapping[str, Any] = t  # read by the table's keys
    ident += [[label, how(given[key])] for key, label, how in _IDENTITY if key in given]
    out += [k.table([[k.p(a), k.p(b)] for a, b in ident], [0.2, 0.8]), k.Spacer(1, 3 * k.mm)]
    return out


#: The turbine's identity as the report writes it: (JSON key, label, value with its unit).
_IDENTITY: tuple[tuple[str, str, Any], ...] = (
    ("manufacturer", "manufacturer", str),
    ("year", "year", str),
    ("rated_power_kw", "rated power", lambda v: f"{v:,.6g} kW"),
    ("rotor_diameter_m", "rotor diameter", lambda v: f"{v:,.6g} m"),
    ("hub_height_m", "hub height", lambda v: f"{v:,.6g} m"),
)


def _warnings(k: _Kit, r: ReportDoc) -> list[Any]:
    """What an importer assumed, suspicious values: before any verdict."""
    if not r["warnings"]:
        return []
    out: list[Any] = [k.p("Warnings", "Heading2")]
    out += [
        k.raw(f'<font color="{STATUS_HEX["warn"]}">• {_esc(w)}</font>', "BodyText")
        for w in r["warnings"]
    ]
    out.append(k.Spacer(1, 3 * k.mm))
    return out


def _summary(k: _Kit, r: ReportDoc) -> list[Any]:
    """Every check in one table: status, margin, DAF, finding."""
    out = k.heading("Summary of checks")
    rows = [k.header("status", "check", "margin", "DAF", "finding")]
    rows += [
        [
            k.status(c["status"]),
            k.ident(c["id"], 0.2),
            k.num(_pct(c.get("margin"))),
            k.num(_num(c.get("daf"))),
            k.p(c["message"]),
        ]
        for c in r["checks"]
    ]
    out.append(k.table(rows, [0.08, 0.2, 0.09, 0.07, 0.56]))
    return out


def _subsystem(
    k: _Kit, r: ReportDoc, sub: str, title: str, pngs: dict[str, bytes], drawn: set[str]
) -> list[Any]:
    """A subsystem's section: its modes, its figures (each once in the report: ``drawn``)
    and its checks with their numbers, rules and sources — or where its modes are judged."""
    modes = [m for m in r["modes"] if m["subsystem"] == sub]
    if not modes and not any(c["subsystem"] == sub for c in r["checks"]):
        return []
    if sub == "aerodynamics" and r.get("damping") != "aeroelastic":
        return []  # a structural audit: said in the identity table and the summary
    if sub == "system" and r.get("results"):  # another tool's modes, not our model
        title = f"Whole turbine: the modes as {r['results']['tool']} computed them"
    out = k.heading(title)
    in_op = any(m.get("damping_in_operation") for m in modes)
    rows = [k.header("mode", "description", "f [Hz]", "ζ (lowest in op.)" if in_op else "ζ")]
    rows += [
        [
            k.ident(m["id"], 0.22),
            k.p(m["description"] + _judged_note(m)),
            k.num(f"{m['frequency_hz']:.4g}"),
            k.num(_num(m["damping_ratio"]) + _in_operation(m)),
        ]
        for m in modes
    ]
    if modes:
        out.append(k.table(rows, [0.22, 0.5, 0.14, 0.14]))
    if sub == "system":
        out += _coupling(k, r["checks"])
    for diagram in DIAGRAM_FOR.get(sub, ()):
        if diagram not in pngs or diagram in drawn:
            continue
        drawn.add(diagram)
        out += [k.Spacer(1, 2 * k.mm), k.image(pngs[diagram], *_fitted(k, _aspect(pngs[diagram])))]
    rows = [k.header("status", "check", "numbers", "rule and source")]
    rows += [
        [
            k.status(c["status"]),
            k.ident(c["id"], 0.2),
            k.p(_numbers(c)),
            k.p(_rule_text(c["rule"], r["rule"])),
        ]
        for c in r["checks"]
        if c["subsystem"] == sub
    ]
    if len(rows) > 1:
        out += [k.Spacer(1, 2 * k.mm), k.table(rows, [0.08, 0.2, 0.36, 0.36])]
    else:  # a table of no rows says nothing: say where its modes are judged
        out.append(k.p(_judged_elsewhere(modes), "BodyText"))
    return out


def _inputs(k: _Kit, r: ReportDoc) -> list[Any]:
    """Every input value with its provenance, source and note."""
    out = k.heading("Inputs and their provenance")
    if not r["inputs"]:
        out.append(
            k.p("No provenance was recorded in the spec: all values are as given.", "BodyText")
        )
        return out
    rows = [k.header("field", "value", "provenance", "source and note")]
    rows += [
        [
            k.ident(path, 0.33),
            k.Paragraph(_for_people(q["value"]), k.numbers),
            k.p(q["provenance"]),
            k.p("; ".join(x for x in (q.get("source"), q.get("note")) if x)),
        ]
        for path, q in r["inputs"].items()
    ]
    out.append(k.table(rows, [0.33, 0.13, 0.15, 0.39]))
    return out


def _uncertainty(k: _Kit, u: UncertaintyDoc) -> list[Any]:
    """The sampled spread of each uncertain mode, its chance of a resonance, and the
    sensitivities of the frequencies to the inputs."""
    out = k.heading(f"Uncertainty ({u['samples']:,} samples, seed {u['seed']})")
    rows = [k.header("mode", "p5 [Hz]", "p50 [Hz]", "p95 [Hz]", "probability in a margin band")]
    for mode, s in u["modes"].items():
        risks = [
            f"{line} {v['probability']:.1%} [{v['ci95'][0]:.1%}–{v['ci95'][1]:.1%}]"
            for line, v in sorted(s.get("in_margin_band", {}).items())
            if v["probability"] > 0
        ]
        if "unstable" in s:
            risks.insert(0, f"buckles {s['unstable']['probability']:.1%}")
        spread = [_num(s.get("p5_hz")), _num(s.get("p50_hz")), _num(s.get("p95_hz"))]
        rows.append([k.ident(mode, 0.25), *map(k.num, spread), k.p(", ".join(risks) or "none")])
    out.append(k.table(rows, [0.25, 0.11, 0.11, 0.11, 0.42]))
    if u.get("sensitivities"):
        out.append(
            k.p(
                "Sensitivities (∂f/∂p)·(p/f): the per-cent change of a frequency per "
                "per cent of the input.",
                "BodyText",
            )
        )
        rows = [k.header("input", "mode", "(∂f/∂p)·(p/f)")]
        for path, per_mode in u["sensitivities"].items():
            for mode, value in sorted(per_mode.items(), key=lambda kv: -abs(kv[1])):
                rows.append([k.ident(path, 0.45), k.ident(mode, 0.35), k.num(f"{value:+.3f}")])
        out.append(k.table(rows, [0.45, 0.35, 0.2]))
    return out


def _footer(canvas, doc) -> None:  # type: ignore[no-untyped-def]
    canvas.saveState()
    canvas.setFont("Helvetica", 7)
    canvas.drawString(doc.leftMargin, 10, f"wtvib {__version__} — vibration audit")
    canvas.drawRightString(doc.pagesize[0] - doc.rightMargin, 10, f"page {doc.page}")
    canvas.restoreState()


def _in_operation(m: ModeDoc) -> str:
    op = m.get("damping_in_operation")
    if not op:
        return ""
    where = (
        f"{op['at_wind_m_s']:.3g} m/s"
        if op["at_wind_m_s"] is not None
        else f"{op['at_rpm']:.3g} rpm"
    )
    return f" ({_num(op['lowest_total_damping_ratio'])} at {where})"


def _fitted(k: _Kit, aspect: float) -> tuple[float, float]:
    """Width and height [pt] of a figure of this aspect: the text width, or less where the
    height would not fit a page."""
    width = min(k.width, k.tallest / aspect) if aspect > 0 else k.width
    return width, width * aspect


def _aspect(data: bytes) -> float:
    """Height over width of a PNG (from its IHDR chunk; 0.7 where it has none)."""
    found = png.header(data)
    return found[1] / found[0] if found is not None and found[0] else 0.7


def _rule_text(check_rule: RuleDoc, margin_rule: RuleSettingsDoc) -> str:
    """The check's rule; its source only where it is not the margin rule stated above."""
    if check_rule["source"] == margin_rule["source"]:
        return f"{check_rule['name']} (margin rule above)"
    return f"{check_rule['name']} — {check_rule['source']}"


def _coupling(k: _Kit, checks: list[CheckDoc]) -> list[Any]:
    """Parked coupled frequencies beside the isolated subsystems' (check system.coupling)."""
    c = next((c for c in checks if c["id"] == "system.coupling"), None)
    if c is None:
        return []
    rows = [
        k.header("coupled mode (standstill)", "f [Hz]", "isolated subsystem", "f [Hz]", "shift")
    ]
    for row in c["modes"]:
        shift = row["change"]
        rows.append(
            [
                k.ident(row["id"], 0.34),
                k.num(f"{row['coupled_hz']:.4g}"),
                k.ident(row["isolated_id"], 0.3) if row["isolated_id"] else k.p("—"),
                k.num("—" if row["isolated_hz"] is None else f"{row['isolated_hz']:.4g}"),
                k.num("—" if shift is None else f"{shift:+.1%}"),
            ]
        )
    return [
        k.Spacer(1, 2 * k.mm),
        k.p(f"Coupled model, {c['condition']}: {'; '.join(c['model'])}.", "BodyText"),
        k.table(rows, [0.34, 0.12, 0.3, 0.12, 0.12]),
    ]


def _judged_elsewhere(modes: Sequence[Mapping[str, Any]]) -> str:
    """Why a subsystem has no checks of its own: where each of its modes is judged."""
    moved = [f"{m['id']} as {m['superseded_by']}" for m in modes if m.get("superseded_by")]
    idle = [m["id"] for m in modes if not m.get("superseded_by") and m.get("regimes") == []]
    rest = [m["id"] for m in modes if not m.get("superseded_by") and m.get("regimes") != []]
    parts = [f"judged in the whole-turbine model: {', '.join(moved)}"] if moved else []
    if idle:
        parts.append(f"in no operating regime: {', '.join(idle)}")
    if rest:
        parts.append(f"no check applies to {', '.join(rest)}")
    return "No checks of its own — " + "; ".join(parts) + "."


def _judged_note(m: Mapping[str, Any]) -> str:
    """Where a mode is not judged, say so beside it (as the terminal and figures do)."""
    if m.get("superseded_by"):
        return f" — isolated value; judged as {m['superseded_by']}"
    if m.get("regimes") == []:
        return " — reported only (exists in no operating regime)"
    return ""


def _worst(checks: list[CheckDoc]) -> CheckDoc | None:
    from ..rules import worst_check

    return worst_check(checks)


#: A check's numbers as people read them: (key, label, how to format the value).
_READABLE: tuple[tuple[str, str, str], ...] = (
    ("mode", "mode", "text"),
    ("frequency_hz", "f", "Hz"),
    ("margin", "margin", "%"),
    ("required_margin", "needs", "%"),
    ("speed_rpm", "at", "rpm"),
    ("excitation_hz", "line at", "Hz"),
    ("daf", "DAF", "daf"),
    ("damping_ratio", "ζ", "ratio"),
    ("regime", "regime", "text"),
    ("crossings_rpm", "crossings", "rpm-list"),
    ("exclude_rpm", "exclude", "rpm-bands"),
    ("tower_class", "class", "text"),
    ("startup_crossings", "start-up crossings", "list"),
    ("speed_ratio", "speed ratio", "num"),
    ("max_multiplier_in_operation", "largest Floquet multiplier", "num"),
    ("unstable_rpm", "unstable at", "rpm-bands"),
    ("min_total_damping_ratio", "lowest ζ", "ratio"),
    ("at_wind_m_s", "at", "m/s"),
    ("at_rpm", "at", "rpm"),
    ("rated_wind_m_s", "rated wind", "m/s"),
    ("tip_speed_ratio", "TSR", "num"),
)


def _numbers(c: CheckDoc) -> str:
    """One readable line of a check's numbers, with units (the JSON keeps full precision)."""
    numbers: Mapping[str, Any] = c  # read by the table's keys
    parts = [
        f"{label} {_readable(numbers[key], how)}"
        for key, label, how in _READABLE
        if numbers.get(key) not in (None, [], "")
    ]
    low = c.get("lowest")
    if isinstance(low, dict) and "mode" in low:  # the stability checks' lowest damping
        z = low.get("damping_ratio", low.get("total_damping_ratio"))
        where = [
            _readable(low[k], u)
            for k, u in (("rpm", "rpm"), ("at_wind_m_s", "m/s"))
            if low.get(k) is not None
        ]
        parts.append(
            f"lowest ζ {_readable(z, 'ratio')} ({low['mode']}"
            + (f", at {', '.join(where)}" if where else "")
            + ")"
        )
    for row in c.get("sets") or []:  # an ElastoDyn deck's polynomials
        if row.get("implied_hz") and row.get("computed_implied_hz"):
            stiff = row["implied_hz"] / row["computed_implied_hz"] - 1
            parts.append(
                f"{row['name']} MAC {row['mac']:.4f}, implies {row['implied_hz']:.4g} Hz "
                f"({words.signed_percent(stiff)} on the computed "
                f"{row['computed_implied_hz']:.4g} Hz)"
            )
    unstable = c.get("unstable")
    if isinstance(unstable, dict) and unstable:  # mode → winds [m/s]
        parts += [
            f"unstable: {m} at {', '.join(f'{w:.3g}' for w in winds)} m/s"
            for m, winds in unstable.items()
        ]
    elif isinstance(unstable, list) and unstable:  # imported results: rows of mode, ζ, rpm
        parts += [
            f"unstable: {u['mode']} ζ {u['damping_ratio']:.3g} at {u['rpm']:.4g} rpm"
            for u in unstable[:4]
        ]
    return "; ".join(parts)


def _readable(value: Any, how: str) -> str:
    if how == "text":
        return str(value)
    if how == "list":
        return ", ".join(map(str, value)) if isinstance(value, list) else str(value)
    if how == "rpm-list":
        return ", ".join(f"{v:.3g}" for v in value) + " rpm"
    if how == "rpm-bands":
        return ", ".join(f"{a:.3g}–{b:.3g}" for a, b in value) + " rpm"
    if not isinstance(value, int | float):
        return str(value)
    if how == "%":
        return "0 %" if abs(value) < 5e-4 else f"{100 * value:.1f} %"
    if how == "daf":
        return f"{value:.2f}"
    if how == "ratio":
        return f"{value:.3g}"
    if how == "num":
        return f"{value:.3g}"
    return f"{value:.4g} {how}"


def _for_people(value: Any) -> str:
    """A number as an engineer writes it, as reportlab markup: 2,275,000 or 2.1×10<super>11
    </super> (the PDF's fonts have no superscript digits), never '2.275e+06'."""
    if not isinstance(value, int | float) or isinstance(value, bool):
        return _esc(str(value))
    v = float(value)
    if v == 0:
        return "0"
    if v.is_integer() and abs(v) < 1e9:
        return f"{int(v):,}"
    if 1e-3 <= abs(v) < 1e6:
        return f"{v:,.6g}"
    mantissa, exponent = f"{v:.4e}".split("e")
    mantissa = mantissa.rstrip("0").rstrip(".")
    return f"{mantissa}×10<super>{int(exponent)}</super>"


def _pct(x: float | None) -> str:
    """A margin in per cent: one decimal, none from 1000 % (``1899 %``, not ``1899.1 %``)."""
    if x is None:
        return ""
    return f"{x:.0%}" if abs(x) >= 10 else f"{x:.1%}"


def _num(x: float | None) -> str:
    return "—" if x is None else f"{x:.3g}"


def _esc(text: str) -> str:
    """Escape plain text for reportlab's mini-markup."""
    return text.replace("&", "&amp;").replace("<", "&lt;").replace(">", "&gt;")
