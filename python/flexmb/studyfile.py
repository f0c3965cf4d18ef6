"""Study files (docs/studies.md): a base model, the parameters to vary and
the outputs to collect, read into a StudySpec whose runs() are the tasks of
a study (plain dicts: they travel to Dask workers as they are).

Errors in the study file raise flexmb.InputError naming the study file and
the key ("study.yaml: parameters.length.path: ...").
"""

import hashlib
import itertools
import json
import math
import os
import re

import yaml

from . import _core

STUDY_KEYS = ("study", "model", "command", "options", "files", "parameters", "table", "outputs", "timeout")
STUDY_PARAMETER_KEYS = ("path", "option", "scale", "values", "range")
STUDY_COMMANDS = ("run", "truck max-speed")
STUDY_REDUCTIONS = ("max", "min", "mean", "rms", "abs_max", "first", "final", "period")
_STUDY_PATH_TOKEN = re.compile(r"([^.\[\]]+)|\[([^\]]*)\]")
_STUDY_OUTPUT = re.compile(r"^\s*(\w+)\(\s*([^()]+?)\s*\)\s*$")


class StudyInputError(_core.InputError):
    """An error of a study file (an InputError naming the file and key)."""


def _fail(file, key, message):
    raise StudyInputError(f"{file}: {key}: {message}" if key else f"{file}: {message}")


def parse_path(file, key, text):
    """Tokens of a dotted key path: str keys, ('name', value) selectors of a
    list element by its name (or another key), and int indices."""
    if not isinstance(text, str) or not text.strip():
        _fail(file, key, "a key path like bodies[name=bob].mass is needed")
    tokens, pos = [], 0
    text = text.strip()
    for m in _STUDY_PATH_TOKEN.finditer(text):
        if m.start() != pos and text[pos:m.start()] != ".":
            _fail(file, key, f"cannot read key path '{text}' at '{text[pos:]}'")
        pos = m.end()
        if m.group(1) is not None:
            word = m.group(1)
            tokens.append(int(word) if word.isdigit() else word)
        else:
            inner = m.group(2).strip()
            if "=" in inner:
                k, v = (s.strip() for s in inner.split("=", 1))
                tokens.append((k, v))
            elif re.fullmatch(r"-?\d+", inner):
                tokens.append(int(inner))
            else:
                _fail(file, key, f"'[{inner}]' in '{text}' is neither an index nor KEY=VALUE")
    if pos != len(text):
        _fail(file, key, f"cannot read key path '{text}' at '{text[pos:]}'")
    return tokens


def _path_text(tokens):
    out = ""
    for t in tokens:
        if isinstance(t, tuple):
            out += f"[{t[0]}={t[1]}]"
        elif isinstance(t, int):
            out += f"[{t}]"
        else:
            out += ("." if out else "") + t
    return out


def set_path(model, tokens, value, file, key):
    """Sets the existing entry at `tokens` of the model (dicts and lists
    from YAML) to value; an entry that does not exist is an error."""
    node = model
    for depth, t in enumerate(tokens):
        here = _path_text(tokens[:depth]) or "the model"
        last = depth == len(tokens) - 1
        if isinstance(t, tuple):
            if not isinstance(node, list):
                _fail(file, key, f"{here} is not a list, cannot select [{t[0]}={t[1]}]")
            hits = [i for i, e in enumerate(node) if isinstance(e, dict) and str(e.get(t[0])) == t[1]]
            if len(hits) != 1:
                names = [str(e.get(t[0])) for e in node if isinstance(e, dict)]
                _fail(file, key, f"{len(hits)} entries of {here} have {t[0]} = {t[1]} (there are: {', '.join(names)})")
            t = hits[0]
        if isinstance(t, int):
            if not isinstance(node, list) or not -len(node) <= t < len(node):
                _fail(file, key, f"{here} has no element [{t}]")
        elif not isinstance(node, dict) or t not in node:
            have = ", ".join(str(k) for k in node) if isinstance(node, dict) else "not a map"
            _fail(file, key, f"{here} has no key '{t}' (it has: {have})")
        if last:
            node[t] = value
        else:
            node = node[t]


def _expand_range(file, key, r):
    if not isinstance(r, dict) or set(r) - {"start", "stop", "step", "count"} or "start" not in r or "stop" not in r:
        _fail(file, key, "a range is {start: A, stop: B, step: S} or {start: A, stop: B, count: N}")
    start, stop = float(r["start"]), float(r["stop"])
    if ("step" in r) == ("count" in r):
        _fail(file, key, "a range needs exactly one of step and count")
    if "count" in r:
        n = int(r["count"])
        if n < 1:
            _fail(file, key, f"count {n}: the range is empty")
        return [start] if n == 1 else [start + (stop - start) * i / (n - 1) for i in range(n)]
    step = float(r["step"])
    if step == 0 or (stop - start) * step < 0:
        _fail(file, key, f"start {start}, stop {stop}, step {step}: the range is empty")
    n = int(math.floor((stop - start) / step + 1e-9)) + 1
    return [start + i * step for i in range(n)]


class StudyParameter:
    """One parameter: where it goes (key paths into the model, or a command
    line option) and its values (None in a table study)."""

    def __init__(self, file, name, spec):
        key = f"parameters.{name}"
        if not isinstance(spec, dict):
            _fail(file, key, "a parameter is a map with path or option, and values or range")
        for k in spec:
            if k not in STUDY_PARAMETER_KEYS:
                _fail(file, f"{key}.{k}", f"unknown key (known: {', '.join(STUDY_PARAMETER_KEYS)})")
        self.name = name
        if ("path" in spec) == ("option" in spec):
            _fail(file, key, "a parameter needs exactly one of path (key path into the model) and option")
        paths = spec.get("path", [])
        paths = paths if isinstance(paths, list) else [paths]
        if "path" in spec and not paths:
            _fail(file, f"{key}.path", "no key path given")
        self.paths = [(p, parse_path(file, f"{key}.path", p)) for p in paths]
        self.option = spec.get("option")
        if self.option is not None and not re.fullmatch(r"[a-z][a-z0-9_-]*", str(self.option)):
            _fail(file, f"{key}.option", f"'{self.option}' is not an option name like speed or t_end")
        self.scale = spec.get("scale")
        if self.scale is not None and not isinstance(self.scale, (int, float)):
            _fail(file, f"{key}.scale", "a number is needed")
        if "values" in spec and "range" in spec:
            _fail(file, key, "give values or range, not both")
        self.values = None
        if "values" in spec:
            vals = spec["values"]
            if not isinstance(vals, list) or not vals:
                _fail(file, f"{key}.values", "a non-empty list is needed")
            self.values = list(vals)  # as YAML read them: 12 stays a whole number (counts)
        elif "range" in spec:
            self.values = _expand_range(file, f"{key}.range", spec["range"])

    def model_value(self, value):
        if self.scale is not None and isinstance(value, float):
            return value * self.scale
        return value


class StudySpec:
    """A study file read and checked: base model, parameters, outputs."""

    def __init__(self, file):
        self.file = os.path.abspath(os.fspath(file))
        f = self.file
        try:
            with open(f) as fh:
                doc = yaml.safe_load(fh)
        except OSError as e:
            raise StudyInputError(f"{f}: cannot read the study file: {e.strerror}") from None
        except yaml.YAMLError as e:
            raise StudyInputError(f"{f}: not a YAML file: {e}") from None
        if not isinstance(doc, dict):
            _fail(f, None, "a study file is a YAML map (keys: " + ", ".join(STUDY_KEYS) + ")")
        for k in doc:
            if k not in STUDY_KEYS:
                _fail(f, k, f"unknown key (known: {', '.join(STUDY_KEYS)})")
        self.name = str(doc.get("study", os.path.splitext(os.path.basename(f))[0]))
        if "model" not in doc:
            _fail(f, "model", "missing: the base model file (relative to the study file)")
        self.model = os.path.normpath(os.path.join(os.path.dirname(f), str(doc["model"])))
        try:
            with open(self.model) as fh:
                self.model_text = fh.read()
            self.model_doc = yaml.safe_load(self.model_text)
        except OSError as e:
            _fail(f, "model", f"cannot read {self.model}: {e.strerror}")
        except yaml.YAMLError as e:
            _fail(f, "model", f"{self.model} is not a YAML file: {e}")
        self.command = str(doc.get("command", "run"))
        if self.command not in STUDY_COMMANDS:
            _fail(f, "command", f"'{self.command}' is not one of: {', '.join(STUDY_COMMANDS)}")
        self.options = doc.get("options") or {}
        if not isinstance(self.options, dict):
            _fail(f, "options", "a map of command line options (e.g. {t_end: 2.0})")
        self.files = self._side_files(doc.get("files"))
        self.timeout = doc.get("timeout")
        if self.timeout is not None and not (isinstance(self.timeout, (int, float)) and self.timeout > 0):
            _fail(f, "timeout", "a positive number of seconds per run is needed")
        params = doc.get("parameters")
        if not isinstance(params, dict) or not params:
            _fail(f, "parameters", "a map of at least one parameter is needed")
        self.parameters = [StudyParameter(f, str(n), s) for n, s in params.items()]
        self.rows = self._rows(doc.get("table"))
        self.outputs = self._outputs(doc.get("outputs"))
        for p in self.parameters:  # every key path must exist in the base model
            for text, tokens in p.paths:
                set_path(yaml.safe_load(self.model_text), tokens, 0.0, f, f"parameters.{p.name}.path ({text})")

    def _side_files(self, files):
        if files is None:
            return None
        if not isinstance(files, list):
            _fail(self.file, "files", "a list of files relative to the model's folder")
        base = os.path.dirname(self.model)
        out = {}
        for name in files:
            name = str(name)
            if os.path.isabs(name) or ".." in name.split("/"):
                _fail(self.file, "files", f"'{name}': only files in or below the model's folder travel with a task")
            try:
                with open(os.path.join(base, name), "rb") as fh:
                    out[name] = fh.read()
            except OSError as e:
                _fail(self.file, "files", f"cannot read {os.path.join(base, name)}: {e.strerror}")
        return out

    def _rows(self, table):
        f = self.file
        names = [p.name for p in self.parameters]
        if table is None:
            for p in self.parameters:
                if p.values is None:
                    _fail(f, f"parameters.{p.name}", "values or range needed (or a table of rows)")
            return [dict(zip(names, combo)) for combo in itertools.product(*(p.values for p in self.parameters))]
        for p in self.parameters:
            if p.values is not None:
                _fail(f, f"parameters.{p.name}", "with a table, the rows give the values (no values or range here)")
        if not isinstance(table, list) or not table:
            _fail(f, "table", "a non-empty list of rows {parameter: value, ...}")
        rows = []
        for i, row in enumerate(table):
            if not isinstance(row, dict) or set(row) != set(names):
                got = ", ".join(row) if isinstance(row, dict) else "not a map"
                _fail(f, f"table[{i}]", f"a row gives every parameter ({', '.join(names)}); it has: {got}")
            rows.append({n: row[n] for n in names})
        return rows

    def _outputs(self, outputs):
        f = self.file
        if not isinstance(outputs, dict) or not outputs:
            _fail(f, "outputs", "a map of at least one output: NAME: summary.KEY or NAME: REDUCTION(COLUMN)")
        out = {}
        for name, spec in outputs.items():
            key = f"outputs.{name}"
            spec = str(spec)
            m = _STUDY_OUTPUT.match(spec)
            if spec.startswith("summary.") and len(spec) > 8:
                out[str(name)] = ("summary", spec[8:])
            elif m:
                if m.group(1) not in STUDY_REDUCTIONS:
                    _fail(f, key, f"unknown reduction '{m.group(1)}' (known: {', '.join(STUDY_REDUCTIONS)})")
                if self.command != "run":
                    _fail(f, key, f"'{self.command}' writes no results.csv; collect summary.KEY outputs")
                out[str(name)] = (m.group(1), m.group(2))
            else:
                _fail(f, key, f"'{spec}' is neither summary.KEY nor REDUCTION(COLUMN), e.g. max(roll_deg)")
        names = {p.name for p in self.parameters}
        for clash in names & set(out) | (names | set(out)) & {"run", "status", "message", "wall_time_s"}:
            _fail(f, "outputs", f"the name '{clash}' is used twice (parameters, outputs, and run, status, "
                                "message, wall_time_s must differ)")
        return out

    def runs(self, cli):
        """The tasks: one dict per run (index 'run', parameter values, the
        model's text with the values set, the command line, side files)."""
        tasks = []
        for i, values in enumerate(self.rows):
            model = yaml.safe_load(self.model_text)
            options = dict(self.options)
            for p in self.parameters:
                v = p.model_value(values[p.name])
                for text, tokens in p.paths:
                    set_path(model, tokens, v, self.file, f"parameters.{p.name}.path ({text})")
                if p.option is not None:
                    options[p.option] = v
            text = yaml.safe_dump(model, sort_keys=False, default_flow_style=None, width=1000)
            tasks.append({
                "run": i, "values": values, "model_name": os.path.basename(self.model), "model_text": text,
                "model_dir": os.path.dirname(self.model), "files": self.files, "cli": cli,
                "command": self.command.split(), "options": options, "outputs": self.outputs,
                "timeout": self.timeout,
            })
        return tasks

    def fingerprint(self, tasks):
        """A hash of what the runs compute (model texts, command lines,
        side files, outputs): a journal of another study is not resumed."""
        h = hashlib.sha256()
        for t in tasks:
            h.update(json.dumps([t["run"], t["values"], t["model_text"], t["command"], t["options"], t["outputs"]],
                                sort_keys=True, default=str).encode())
            for name, data in sorted((t["files"] or {}).items()):
                h.update(name.encode() + hashlib.sha256(data).digest())
        return h.hexdigest()


def load_study(file):
    """Reads and checks a study file (docs/studies.md); a StudySpec."""
    return StudySpec(file)
