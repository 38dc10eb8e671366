"""The Python module (import contactlab): a Simulation stepped equals one run, its in-memory
results equal the files `contactlab run` writes, scenes as dicts and text, bad input as
InputError with nothing written, and the same numbers as the `contactlab` command. Run with
PYTHONPATH=<build>/python; argv[1]: the scenes folder, argv[2]: the contactlab executable.
"""
import csv
import json
import math
import os
import shutil
import subprocess
import sys
import tempfile
import unittest

import numpy as np
import yaml

import contactlab

SCENES = sys.argv.pop(1) if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__),
                                                                   "..", "..", "scenes")
EXE = sys.argv.pop(1) if len(sys.argv) > 1 else "contactlab"
HERTZ = os.path.join(SCENES, "hertz-2d.yaml")
# Four steps, a coarser mesh: a few seconds.
SMALL = {"Load Steps/Steps": 4, "Output/VTK": False}


class Folder:
    """A temporary folder of this process, removed after the test."""

    def __enter__(self):
        self.path = tempfile.mkdtemp(prefix="contactlab-python-")
        return self.path

    def __exit__(self, *exc):
        shutil.rmtree(self.path, ignore_errors=True)


def read_csv(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


class SimulationTest(unittest.TestCase):
    def test_steps_equal_one_run_and_the_files(self):
        with Folder() as out:
            whole = contactlab.Simulation(HERTZ, set=SMALL, out=os.path.join(out, "run"),
                                          quiet=True)
            report = whole.run()
            self.assertTrue(report["converged"], report)
            self.assertEqual(whole.finish(), 0)

            stepped = contactlab.Simulation(HERTZ, set=SMALL, out=os.path.join(out, "step"),
                                            quiet=True)
            times = []
            while stepped.step():
                times.append(stepped.time)
                self.assertEqual(len(stepped.history["time"]), len(times))
                # Built once per step: the reads until the next step share the arrays, which
                # are read-only.
                self.assertIs(stepped.history["normal_force"], stepped.history["normal_force"])
                self.assertFalse(stepped.history["time"].flags.writeable)
            self.assertTrue(stepped.ended)
            self.assertFalse(stepped.step())  # nothing more to do
            self.assertEqual(stepped.finish(), 0)
            self.assertEqual(len(times), 4)
            np.testing.assert_allclose(times, [0.25, 0.5, 0.75, 1.0], rtol=1e-12)

            # Step by step is the uninterrupted run: same iterates, same counts.
            a, b = whole.history, stepped.history
            np.testing.assert_array_equal(a["time"], b["time"])
            np.testing.assert_array_equal(a["newton_iterations"], b["newton_iterations"])
            np.testing.assert_allclose(a["normal_force"], b["normal_force"], rtol=1e-12)
            self.assertEqual(whole.report["iterations"], stepped.report["iterations"])
            self.assertEqual(whole.summary["iterations"], stepped.summary["iterations"])
            self.assertEqual(whole.summary["iterations"]["newton"], whole.report["iterations"])
            pa, pb = whole.contact_points(), stepped.contact_points()
            np.testing.assert_allclose(pa["pressure"], pb["pressure"], rtol=1e-10, atol=1e-12)

            # The memory holds what the files hold.
            rows = read_csv(os.path.join(out, "run", "steps.csv"))
            self.assertEqual(len(rows), len(a["time"]))
            np.testing.assert_allclose([float(r["normal_force"]) for r in rows],
                                       a["normal_force"], rtol=1e-9)
            np.testing.assert_allclose([float(r["contact_force_y"]) for r in rows],
                                       a["contact_force"][:, 1], rtol=1e-9)
            np.testing.assert_array_equal([int(r["newton_iterations"]) for r in rows],
                                          a["newton_iterations"])
            points = read_csv(os.path.join(out, "run", "contact.csv"))
            self.assertEqual(len(points), len(pa["pressure"]))
            np.testing.assert_allclose([float(r["pressure"]) for r in points], pa["pressure"],
                                       rtol=1e-9, atol=1e-12)
            np.testing.assert_array_equal([int(r["node"]) for r in points], pa["node"])
            with open(os.path.join(out, "run", "summary.json")) as f:
                self.assertEqual(json.load(f)["iterations"], whole.summary["iterations"])

            # Hertz: the contact force is the applied load at the last step, and the points'
            # pressures integrate to it.
            self.assertGreater(a["normal_force"][-1], 0)
            np.testing.assert_allclose(np.sum(pa["weight"] * pa["pressure"]),
                                       a["normal_force"][-1], rtol=1e-9)
            u = whole.displacement()
            self.assertEqual(u.shape, (len(whole.node_ids()), 2))
            self.assertEqual(whole.coordinates().shape, (len(whole.node_ids()), 3))
            self.assertTrue(np.all(np.isfinite(u)))
            self.assertGreater(np.max(np.abs(u)), 0)

    def test_the_same_numbers_as_the_command(self):
        with Folder() as out:
            sim = contactlab.run(HERTZ, set=SMALL, out=os.path.join(out, "python"), quiet=True)
            command = [EXE, "run", HERTZ, "--out", os.path.join(out, "command"), "--quiet"]
            for key, value in SMALL.items():
                command += ["--set", f"{key}={str(value).lower()}"]
            done = subprocess.run(command, capture_output=True, text=True, timeout=300)
            self.assertEqual(done.returncode, 0, done.stdout + done.stderr)
            for name in ("steps.csv", "contact.csv"):
                a = read_csv(os.path.join(out, "python", name))
                b = read_csv(os.path.join(out, "command", name))
                self.assertEqual(len(a), len(b), name)
                # Every column but the seconds: the same run, to the digit.
                for ra, rb in zip(a, b):
                    for key in ra:
                        if not key.endswith("_s"):
                            self.assertEqual(ra[key], rb[key], (name, key))
            with open(os.path.join(out, "command", "summary.json")) as f:
                summary = json.load(f)
            self.assertEqual(summary["iterations"], sim.summary["iterations"])
            self.assertEqual(summary["contact"], sim.summary["contact"])

    def test_steps_keep_slow_dynamics_velocity(self):
        # nearly-free-2d under slow dynamics (its regression rows' settings, four steps): each
        # step's inertia is measured from a predictor that extrapolates the last step's
        # velocity, which stepping must carry from one step() to the next.
        scene = os.path.join(SCENES, "nearly-free-2d.yaml")
        with Folder() as out:
            settings = {"Output/VTK": False, "Load Steps/Steps": 4,
                        "Algorithm/Regularization": "slow-dynamics",
                        "Algorithm/slow-dynamics/Time Scale": 3e-3}
            whole = contactlab.run(scene, set=settings,
                                   out=os.path.join(out, "run"), quiet=True)
            stepped = contactlab.Simulation(scene, set=settings,
                                            out=os.path.join(out, "step"), quiet=True)
            while stepped.step():
                pass
            self.assertEqual(stepped.finish(), 0)
            self.assertGreater(len(whole.history["time"]), 1)
            np.testing.assert_array_equal(whole.history["newton_iterations"],
                                          stepped.history["newton_iterations"])
            np.testing.assert_allclose(whole.displacement(), stepped.displacement(), rtol=0,
                                       atol=1e-12 * np.max(np.abs(whole.displacement())))

    def test_restart_from_a_stopped_simulation(self):
        with Folder() as out:
            whole = contactlab.run(HERTZ, set=SMALL, out=os.path.join(out, "whole"), quiet=True)
            first = contactlab.Simulation(HERTZ, set=SMALL, out=os.path.join(out, "cut"),
                                          quiet=True)
            self.assertTrue(first.step() and first.step())
            del first  # stopped after two steps, never finished: its checkpoint is step 2's
            rest = contactlab.Simulation(restart=os.path.join(out, "cut"), quiet=True)
            self.assertEqual(rest.time, 0.5)
            rest.run()
            self.assertEqual(rest.finish(), 0)
            self.assertEqual(len(rest.history["time"]), 2)
            self.assertEqual(rest.summary["load_steps"]["converged"], 4)
            np.testing.assert_allclose(rest.history["normal_force"], whole.history["normal_force"][2:],
                                       rtol=1e-12)
            rows = read_csv(os.path.join(out, "cut", "steps.csv"))
            self.assertEqual([int(r["step"]) for r in rows], [1, 2, 3, 4])

    def test_scene_as_dict_and_text(self):
        with open(HERTZ) as f:
            text = f.read()
        scene = yaml.safe_load(text)
        with Folder() as out:
            forces = []
            for kind, value in (("path", HERTZ), ("text", text), ("scene", scene)):
                kwargs = {kind: value} if kind != "path" else {}
                sim = contactlab.run(HERTZ if kind == "path" else None, set=SMALL,
                                     out=os.path.join(out, kind), quiet=True, **kwargs)
                self.assertTrue(sim.report["converged"], (kind, sim.report))
                forces.append(sim.history["normal_force"][-1])
            self.assertEqual(forces[0], forces[1])
            self.assertEqual(forces[0], forces[2])

    def test_bad_input_raises_and_writes_nothing(self):
        with Folder() as out:
            target = os.path.join(out, "never")
            with self.assertRaises(contactlab.InputError) as caught:
                contactlab.Simulation(HERTZ, set={"Load Steps/Steps": -3}, out=target,
                                      quiet=True)
            self.assertIn("Steps", str(caught.exception))
            self.assertIsInstance(caught.exception, ValueError)
            self.assertFalse(os.path.exists(target))
            with self.assertRaises(contactlab.InputError):
                contactlab.Simulation(os.path.join(out, "missing.yaml"), out=target)
            with self.assertRaises(ValueError):
                contactlab.Simulation(HERTZ, text="Name: x")
            # validate builds without touching the folder, and cannot step.
            checked = contactlab.validate(HERTZ, set=SMALL, out=target, quiet=True)
            self.assertFalse(checked.step())
            self.assertFalse(os.path.exists(target))

    def test_critical_mu_and_iterates(self):
        with Folder() as out:
            sim = contactlab.Simulation(os.path.join(SCENES, "pad-2d.yaml"), out=out, quiet=True,
                                        set={"Output/VTK": False}, critical_mu=True)
            iterates = []
            sim.on_iteration(iterates.append)
            sim.run()
            self.assertEqual(sim.finish(), 0)
            # As `contactlab critical-mu` (tests/app/check_critical_mu.py): mu = 0.45 is below
            # the pad's critical mu, which is mu times the pattern's factor.
            crit = sim.summary["critical_mu"]
            self.assertTrue(crit["computed"], crit)
            self.assertGreater(crit["zones"]["floor"], 0.45)
            self.assertLessEqual(abs(crit["zones"]["floor"] - 0.45 * crit["factor"]),
                                 1e-12 * crit["zones"]["floor"])
            # Every Newton iterate was observed, each step's last below its target.
            self.assertGreaterEqual(len(iterates), sim.report["iterations"])
            last = {}
            for p in iterates:
                last[p["step"]] = p
            self.assertEqual(sorted(last), list(range(1, sim.report["steps"] + 1)))
            for p in last.values():
                self.assertLessEqual(p["residual"], p["target"] * (1 + 1e-12) + 1e-300, p)

    def test_an_observer_that_raises_leaves_the_last_converged_step(self):
        with Folder() as out:
            sim = contactlab.Simulation(HERTZ, set=SMALL, out=out, quiet=True)

            def stop_in_step_two(progress):
                if progress["step"] == 2:
                    raise KeyError("stop")

            sim.on_iteration(stop_in_step_two)
            with self.assertRaises(KeyError):
                sim.run()
            self.assertEqual(sim.time, 0.25)
            self.assertEqual(sim.report["steps"], 1)
            self.assertFalse(sim.ended)
            sim.on_iteration(None)
            sim.run()
            self.assertEqual(sim.finish(), 0)
            whole = contactlab.run(HERTZ, set=SMALL, out=os.path.join(out, "whole"), quiet=True)
            np.testing.assert_allclose(sim.history["normal_force"], whole.history["normal_force"],
                                       rtol=1e-9)

    def test_study_table(self):
        with Folder() as out:
            path = os.path.join(out, "study.yaml")
            with open(path, "w") as f:
                yaml.safe_dump({"contactlab-study": {
                    "Name": "python-study", "Scene": os.path.abspath(HERTZ), "Timeout": 300,
                    "Sets": ["Output/VTK=false"],
                    "Axes": {"Algorithm/Method": ["generalized-newton", "fixed-point"]},
                    "Reference": {"Type": "analytic", "Name": "hertz-2d", "Radius": 1.0,
                                  "E": 1.0, "nu": 0.3, "Centre": [0.0]}}}, f)
            rows = contactlab.study(path, os.path.join(out, "result"))
            self.assertEqual([r["Algorithm/Method"] for r in rows],
                             ["generalized-newton", "fixed-point"])
            for r in rows:
                self.assertEqual(r["status"], "converged", r)
                self.assertGreater(r["newton"], 0)
                self.assertLess(r["pressure_error_l2"], 0.05)
            # The study's first run is the scene with that method: the same Newton count.
            sim = contactlab.run(HERTZ, set={"Output/VTK": False,
                                             "Algorithm/Method": "generalized-newton"},
                                 out=os.path.join(out, "one"), quiet=True)
            self.assertEqual(rows[0]["newton"], sim.report["iterations"])
            with open(path, "w") as f:
                f.write("contactlab-study: {Name: broken}\n")
            with self.assertRaises(contactlab.InputError):
                contactlab.study(path, os.path.join(out, "broken"))

    def test_finished_before_its_end_is_stopped(self):
        with Folder() as out:
            sim = contactlab.Simulation(HERTZ, set=SMALL, out=out, quiet=True)
            self.assertTrue(sim.step())
            self.assertEqual(sim.finish(), 1)
            self.assertFalse(sim.summary["converged"])
            self.assertEqual(sim.summary["failure"], "stopped")
            self.assertIn("before Load Steps/End Time = 1", sim.summary["message"])
            self.assertEqual(sim.summary["load_steps"]["converged"], 1)
            with self.assertRaises(RuntimeError):
                sim.finish()  # once

    def test_nodal_fields_known_states(self):
        with Folder() as out:
            # Uniaxial compression (hex27): sigma_zz = -2000 at every node, nothing else.
            block = contactlab.run(os.path.join(SCENES, "block-compression-3d.yaml"),
                                   set={"Output/VTK": False}, out=os.path.join(out, "block"),
                                   quiet=True)
            f = block.nodal_fields()
            self.assertEqual(f["stress"].shape, (len(block.node_ids()), 6))
            self.assertNotIn("equivalent_plastic_strain", f)
            np.testing.assert_allclose(f["stress"][:, 2], -2000.0, rtol=1e-9)
            np.testing.assert_allclose(f["stress"][:, [0, 1, 3, 4, 5]], 0.0, atol=1e-7)
            np.testing.assert_allclose(f["von_mises"], 2000.0, rtol=1e-9)
            # The plastic strip at Hill's plane-strain limit, homogeneous: sigma_xx = 2 sigma_y /
            # sqrt 3, sigma_zz half of it, von Mises sigma_y = 250, the plastic strain uniform
            # and the summary's largest.
            strip = contactlab.run(os.path.join(SCENES, "plastic-strip-2d.yaml"),
                                   set={"Output/VTK": False}, out=os.path.join(out, "strip"),
                                   quiet=True)
            f = strip.nodal_fields()
            np.testing.assert_allclose(f["stress"][:, 0], 500 / np.sqrt(3), rtol=1e-3)
            np.testing.assert_allclose(f["stress"][:, 2], 250 / np.sqrt(3), rtol=1e-3)
            np.testing.assert_allclose(f["von_mises"], 250.0, rtol=1e-6)
            eps = f["equivalent_plastic_strain"]
            self.assertGreater(np.min(eps), 0.04)
            np.testing.assert_allclose(eps, strip.summary["plasticity"]["max_equivalent_plastic_strain"],
                                       rtol=1e-9)

    def test_a_failed_run_reports_and_keeps_its_steps(self):
        with Folder() as out:
            # Two Newton iterations cannot solve the contact step: the run fails at step 1.
            sim = contactlab.Simulation(HERTZ, set=dict(SMALL, **{"Newton/Max Iterations": 1}),
                                        out=out, quiet=True)
            self.assertFalse(sim.step())
            self.assertTrue(sim.ended)
            self.assertFalse(sim.report["converged"])
            self.assertTrue(sim.report["failure"])
            self.assertEqual(sim.finish(), 1)
            self.assertFalse(sim.summary["converged"])
            self.assertEqual(len(sim.history["time"]), 0)


if __name__ == "__main__":
    unittest.main()
