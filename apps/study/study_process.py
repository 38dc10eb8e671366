"""How a study's runs are started: each its own `contactlab run` process, or all in one
`contactlab batch` process (the default), which pays the start-up once and hands each run the
linear solver the run before it left (doc/studies.md, "Process Per Run"). Either way a run has
a time limit, and a crash or a timeout is the run's outcome, not the study's: the batch process
is started again for the next run."""
import os
import select
import signal
import subprocess
import time


def _kill(proc):
    """Stops `proc` and anything it started (it leads a session of its own)."""
    try:
        os.killpg(proc.pid, signal.SIGKILL)
    except ProcessLookupError:
        pass
    proc.wait()


def run_own_process(exe, scene, folder, sets, timeout):
    """One `contactlab run`; its exit code, negative for a signal, None after the timeout."""
    cmd = [exe, "run", scene, "--out", folder]
    for s in sets:
        cmd += ["--set", s]
    with open(os.path.join(folder, "run.log"), "w") as log:
        # A session of its own, so that a timeout stops the run and anything it started.
        proc = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT,
                                start_new_session=True)
        try:
            return proc.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            _kill(proc)
            return None


class BatchProcess:
    """A `contactlab batch` process: run() sends it one run (a tab-separated line) and reads
    its answer, "exit CODE", within the timeout."""

    def __init__(self, exe):
        self.exe = exe
        self.proc = None
        self.pending = b""

    @staticmethod
    def accepts(scene, folder, sets):
        """A run the line format can carry (no tab or newline in any field)."""
        return not any("\t" in f or "\n" in f for f in [scene, folder, *sets])

    def run(self, scene, folder, sets, timeout):
        """The run's exit code, negative for the signal that ended the process during it, None
        after the timeout (the process is then stopped; the next run starts another)."""
        if self.proc is None:
            self.proc = subprocess.Popen([self.exe, "batch"], stdin=subprocess.PIPE,
                                         stdout=subprocess.PIPE, start_new_session=True)
            self.pending = b""
        line = "\t".join([os.path.abspath(folder), scene, *sets]) + "\n"
        try:
            self.proc.stdin.write(line.encode())
            self.proc.stdin.flush()
        except BrokenPipeError:
            return self._ended()
        answer = self._answer(time.monotonic() + timeout)
        if answer is None:
            _kill(self.proc)
            self.proc = None
            return None
        if answer == "":
            return self._ended()
        code = int(answer.split()[1])
        if code >= 128:  # interrupted: the batch stops with its run
            self.proc.wait()
            self.proc = None
        return code

    def _answer(self, deadline):
        """The next line of the process's stdout ('' at its end), None past the deadline."""
        fd = self.proc.stdout.fileno()
        while b"\n" not in self.pending:
            left = deadline - time.monotonic()
            if left <= 0:
                return None
            ready, _, _ = select.select([fd], [], [], left)
            if not ready:
                continue
            chunk = os.read(fd, 4096)
            if not chunk:
                return ""
            self.pending += chunk
        line, self.pending = self.pending.split(b"\n", 1)
        return line.decode()

    def _ended(self):
        """The process ended during a run: its exit status (negative: the signal)."""
        code = self.proc.wait()
        self.proc = None
        return code if code < 0 else (code or 1)

    def close(self):
        if self.proc is not None:
            try:
                self.proc.stdin.close()
                self.proc.wait(timeout=10)
            except (OSError, subprocess.TimeoutExpired):
                _kill(self.proc)
            self.proc = None

    def stop(self):
        """At once (the study is interrupted): the run under way is killed."""
        if self.proc is not None:
            _kill(self.proc)
            self.proc = None
