"""What each option of the commands does, in the words ``--help`` shows: one wording per
idea, by the key the command line's declaration names (``check.out`` where one command's
option of a shared name says something else). The standard library only: the command line
reads it before numpy loads."""

#: Every option's help, by the key its declaration names.
HELP = {
    "rpm": "Operating range [rpm] (or one fixed speed) for imports that do not give it.",
    "rated": "Rated speed [rpm].",
    "head_mass": "Tower-head mass [kg] for windIO files (1.x hold no hub/nacelle): the "
    "whole rotor-nacelle assembly, blades included.",
    "clamped_base": "Read a floating turbine's tower (windIO, OpenFAST) as clamped at its base "
    "(said in the report; platform and moorings are not modelled).",
    "deck_dofs": "Model an OpenFAST deck with the degrees of freedom it switches on (FlapDOF1 … "
    "PtfmYDOF), as OpenFAST does; by default every mode is audited and the switches said.",
    "soil": "Soil profile (YAML: soil layers, bounds) for a windIO monopile.",
    "blades": "Number of blades, for Campbell results that do not say.",
    "margin": "Margin, e.g. 0.05 (overrides the spec).",
    "rule": "Margin rule (overrides the spec).",
    "preset": "Code preset for rule and margin.",
    "help_all": "Show every option (import, rule, figure and study options too).",
    "uncertainty": "Propagate the spec's tolerances (Monte Carlo).",
    "samples": "Monte Carlo samples (2,000); needs --uncertainty.",
    "seed": "Seed of the sampling (0); needs --uncertainty.",
    "scheduler": "Sample on a Dask scheduler (tcp://host:8786); needs --uncertainty.",
    "debug": "Show tracebacks for errors.",
    "version": "Print the version.",
    "force": "Replace existing output files not written by wtvib.",
    "format": "Output format.",
    "no_plots": "Write no figures.",
    "strict": "Exit 1 on warn as well as fail.",
    "spec": "Turbine file: a wtvib spec, a windIO turbine YAML, an OpenFAST deck (.fst or "
    "ElastoDyn .dat), a HAWC2 model (.htc), or another tool's Campbell results (.cmb, .csv, "
    ".lin, a linearisation folder).",
    "check.out": "Folder for the figures (default: the current directory).",
    "detail": "Print the tables of modes and checks too.",
    "campbell_csv": "Write the Campbell data (each judged mode's frequency and damping per "
    "operating point) as CSV.",
    "show_all": "Show passing minor checks too.",
    "figures": "main: the Campbell diagrams and damping; all: the detail figures too.",
    "report.output": "PDF file to write.",
    "inputs": "Spec files or folders.",
    "batch.out": "Folder for the JSON, CSV, PNG and PDF files.",
    "jobs": "Processes (default: all cores).",
    "batch.no_plots": "Write no figures and no PDF report.",
    "sort": "Order of the summary table.",
    "batch.scheduler": "Audit on a Dask scheduler's workers (tcp://host:8786), not locally.",
    "window.out": "Folder for the figure (default: the current directory).",
    "size.spec": "Turbine spec with tower sections.",
    "target": "Window to land in (its middle).",
    "target_hz": "Or a first bending frequency [Hz].",
    "scale": "What to scale.",
    "convert.source": "windIO YAML, OpenFAST deck or Campbell results to convert.",
    "convert.output": "wtvib spec to write.",
    "convert.force": "Replace an existing file.",
    "deck": "ElastoDyn main file (.dat), or the OpenFAST .fst that names it.",
    "shapes.output": "Folder for tower and blade files with the computed polynomials (never the "
    "deck's own).",
    "shapes.rpm": "Rotor speed [rpm] of the blade shapes (default: the highest steady speed).",
    "copy": "Write the catalogue's specs into DIR, to edit.",
    "schema.report": "The report's schema (wtvib-report/1) instead.",
}
