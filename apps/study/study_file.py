"""The study file (doc/studies.md): read, validated with a sentence for every mistake, and
expanded into its cases."""
import itertools
import os
import re

import yaml

from study_metrics import ANALYTIC

KEYS = {
    "Name": "the study's name (the default output folder is study-<Name>)",
    "Description": "free text, copied to study.md",
    "Scene": "the base scene, a path relative to the study file",
    "Timeout": "seconds allowed to each run before it is stopped and recorded as `timeout` "
               "(default 600)",
    "Sets": "--set arguments applied to every run, e.g. [\"Output/VTK=false\"]",
    "Axes": "mapping of a scene key path to its list of values; the study runs their product",
    "Cases": "explicit cases, each {Name: ..., Sets: [...]} and optionally Scene: (another "
             "scene, relative to the study file), run after the product",
    "Cross": "true: every case is run at every point of the axes' product (a case x axes "
             "table, e.g. each extreme with each algorithm); default false",
    "Reference": "accuracy reference: {Type: analytic, Name: hertz-2d, ...parameters}, "
                 "{Type: run, Sets: [...]} (a run of the base scene, usually the finest and "
                 "tightest settings) or {Type: none}",
    "Accuracy Target": "relative L2 error the recommendation asks for: the pressure's, or the "
                       "shear traction's for a shear-only reference (default 0.05)",
    "Zone": "contact zone whose tractions are compared (default: every zone)",
    "Process Per Run": "true: each run is a `contactlab run` process of its own; default "
                       "false: the runs share one `contactlab batch` process (the start-up "
                       "paid once; a run takes the last run's linear solver, whose factors it "
                       "corrects where its matrices differ: the same results to the solver's "
                       "tolerance). A crash or a timeout ends only its run either way",
    "Parallel Runs": "how many runs go at once, each batch process (or run) with an equal "
                     "share of the cores' BLAS threads: a number, or automatic (the default): "
                     "after the first run, as many as the cores while that many copies of its "
                     "peak memory fit in half the machine's, else 1. Run i goes to process "
                     "i mod N, so a study's results do not depend on which run finished first",
}


class StudyError(Exception):
    pass


def _value(v):
    """A YAML scalar as the --set text."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, float):
        return repr(v)
    return str(v)


def _slug(text):
    return re.sub(r"[^A-Za-z0-9.+-]+", "_", text).strip("_")[:80]


def read_study(path):
    try:
        doc = yaml.safe_load(open(path))
    except OSError as e:
        raise StudyError(f"cannot read {path}: {e.strerror}")
    except yaml.YAMLError as e:
        raise StudyError(f"{path}: not valid YAML: {e}")
    if not isinstance(doc, dict) or "contactlab-study" not in doc:
        raise StudyError(f"{path}: the top-level key must be 'contactlab-study'")
    s = doc["contactlab-study"]
    if not isinstance(s, dict):
        raise StudyError(f"{path}: 'contactlab-study' must be a mapping")
    unknown = [k for k in s if k not in KEYS]
    if unknown:
        raise StudyError(f"{path}: unknown key(s) {', '.join(map(str, unknown))}; valid keys: "
                         + ", ".join(KEYS))
    if "Name" not in s or "Scene" not in s:
        raise StudyError(f"{path}: 'Name' and 'Scene' are required")
    name = str(s["Name"])
    if not name.strip() or "/" in name or ".." in name or any(ord(c) < 32 for c in name):
        raise StudyError(f"{path}: Name {name!r} cannot name the output folder study-<Name>: give "
                         "a plain name, without '/', '..' or control characters (such as "
                         "'hertz-2d')")
    s["Scene"] = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(path)),
                                               str(s["Scene"])))
    if not os.path.exists(s["Scene"]):
        raise StudyError(f"{path}: Scene {s['Scene']} does not exist")
    s.setdefault("Timeout", 600)
    if not isinstance(s["Timeout"], (int, float)) or s["Timeout"] <= 0:
        raise StudyError(f"{path}: Timeout must be a positive number of seconds")
    s.setdefault("Process Per Run", False)
    if not isinstance(s["Process Per Run"], bool):
        raise StudyError(f"{path}: Process Per Run must be true or false")
    s.setdefault("Parallel Runs", "automatic")
    if s["Parallel Runs"] != "automatic" and (
            isinstance(s["Parallel Runs"], bool) or not isinstance(s["Parallel Runs"], int) or
            s["Parallel Runs"] < 1):
        raise StudyError(f"{path}: Parallel Runs must be a whole number of at least 1 or "
                         f"automatic (got {s['Parallel Runs']!r})")
    s.setdefault("Accuracy Target", 0.05)
    s.setdefault("Sets", [])
    s.setdefault("Axes", {})
    s.setdefault("Cases", [])
    if not isinstance(s["Sets"], list):
        raise StudyError(f"{path}: Sets must be a list of 'key=value' strings")
    if not isinstance(s["Axes"], dict) or any(not isinstance(v, list) or not v
                                              for v in s["Axes"].values()):
        raise StudyError(f"{path}: Axes must map each scene key path to a non-empty list")
    s.setdefault("Cross", False)
    for c in s["Cases"]:
        if not isinstance(c, dict) or "Name" not in c or not isinstance(c.get("Sets", []), list):
            raise StudyError(f"{path}: each of Cases must be {{Name: ..., Sets: [...]}}")
        unknown = [k for k in c if k not in ("Name", "Sets", "Scene")]
        if unknown:
            raise StudyError(f"{path}: case {c['Name']}: unknown key(s) {', '.join(unknown)}; "
                             "valid keys: Name, Sets, Scene")
        if "Scene" in c:
            c["Scene"] = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(path)),
                                                       str(c["Scene"])))
            if not os.path.exists(c["Scene"]):
                raise StudyError(f"{path}: case {c['Name']}: Scene {c['Scene']} does not exist")
    if not s["Axes"] and not s["Cases"]:
        raise StudyError(f"{path}: no Axes and no Cases: nothing to run")
    ref = s.setdefault("Reference", {"Type": "none"})
    kind = ref.get("Type")
    if kind == "analytic":
        if ref.get("Name") not in ANALYTIC:
            raise StudyError(f"{path}: Reference/Name must be one of {', '.join(ANALYTIC)}")
        missing = [p for p in ANALYTIC[ref["Name"]][1] if p not in ref]
        if ref["Name"] != "coulomb" and "E Star" not in ref and ("E" not in ref or "nu" not in ref):
            missing.append("E Star (or E and nu)")
        if missing:
            raise StudyError(f"{path}: the {ref['Name']} reference needs {', '.join(missing)}")
    elif kind == "run":
        ref.setdefault("Sets", [])
    elif kind != "none":
        raise StudyError(f"{path}: Reference/Type must be analytic, run or none")
    return s


def label(point):
    """A point of the axes' product as a run's name: 'Type=penalty,Method=fixed-point'."""
    return ",".join(f"{k.split('/')[-1]}={v}" for k, v in point.items() if v != "")


def explicit_case(name, point):
    """The explicit case a run named `name` at `point` belongs to: '' for a point of the
    product, the case's own name for a case (crossed ones are named '<case>,<point>')."""
    own = label(point)
    if not own:
        return name
    return name[:-len(own) - 1] if name.endswith("," + own) else ""


def cases(study):
    """[(name, {axis: value}, [--set ...], scene)]: the product of the axes, then the explicit
    cases; with Cross, every case at every point of the product."""
    points = [({}, [])]
    axes = list(study["Axes"].items())
    if axes:
        points = []
        for values in itertools.product(*[v for _, v in axes]):
            point = {k: _value(v) for (k, _), v in zip(axes, values)}
            points.append((point, [f"{k}={v}" for k, v in point.items()]))

    explicit = [(str(c["Name"]), [str(x) for x in c.get("Sets", [])],
                 c.get("Scene", study["Scene"])) for c in study["Cases"]]
    if study["Cross"] and explicit:
        return [(f"{name},{label(point)}" if point else name, point, sets + psets, scene)
                for name, sets, scene in explicit for point, psets in points]
    out = [(label(point), point, psets, study["Scene"]) for point, psets in points if point]
    return out + [(name, {}, sets, scene) for name, sets, scene in explicit]


def run_folder(index, name):
    return f"{index:03d}-{_slug(name)}"
