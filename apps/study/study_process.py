"""How a study's runs are started: each its own `contactlab run` process, or in a
`contactlab batch` process (the default), which pays the start-up once and hands each run the
linear solver the run before it left (doc/studies.md, "Process Per Run"); a Runner is one such
lane, and a study runs as many lanes at once as Parallel Runs says, each with its share of the
BLAS threads. Either way a run has a time limit, and a crash or a timeout is the run's outcome,
not the study's: the batch process is started again for the next run."""
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


def usable_cores():
    """The processors this process may run on."""
    try:
        return len(os.sched_getaffinity(0))
    except AttributeError:
        return os.cpu_count() or 1


def memory_mb():
    """The machine's memory (MemTotal), in MiB; None where /proc/meminfo is not."""
    try:
        for line in open("/proc/meminfo"):
            if line.startswith("MemTotal:"):
                return int(line.split()[1]) / 1024
    except OSError:
        pass
    return None


def blas_share(runners):
    """The environment of a process that shares the cores with runners - 1 others: each gets
    an equal share of BLAS threads (OpenBLAS' threads would otherwise take every core in every
    process, and spin). A user's own OPENBLAS_NUM_THREADS or OMP_NUM_THREADS wins; None for one
    runner (contactlab then shares the cores among its own ranks)."""
    if runners <= 1 or "OPENBLAS_NUM_THREADS" in os.environ or "OMP_NUM_THREADS" in os.environ:
        return None
    return dict(os.environ, OPENBLAS_NUM_THREADS=str(max(1, usable_cores() // runners)))


def run_own_process(exe, scene, folder, sets, timeout, env=None, started=None):
    """One `contactlab run`; its exit code, negative for a signal, None after the timeout.
    `started(proc)`, if given, is told the process (so that another thread can stop it); an
    interruption stops it too."""
    cmd = [exe, "run", scene, "--out", folder]
    for s in sets:
        cmd += ["--set", s]
    with open(os.path.join(folder, "run.log"), "w") as log:
        # A session of its own, so that a timeout stops the run and anything it started.
        proc = subprocess.Popen(cmd, stdout=log, stderr=subprocess.STDOUT,
                                start_new_session=True, env=env)
        if started:
            started(proc)
        try:
            return proc.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            _kill(proc)
            return None
        except BaseException:  # the study was interrupted: its run goes with it
            _kill(proc)
            raise


class BatchProcess:
    """A `contactlab batch` process: run() sends it one run (a tab-separated line) and reads
    its answer, "exit CODE", within the timeout."""

    def __init__(self, exe, env=None):
        self.exe = exe
        self.env = env
        self.proc = None
        self.pending = b""

    @staticmethod
    def accepts(scene, folder, sets):
        """A run the line format can carry (no tab or newline in any field)."""
        return not any("\t" in f or "\n" in f for f in [scene, folder, *sets])

    def start(self):
        """Starts the process, if it is not running (its start-up then overlaps other work)."""
        if self.proc is None:
            self.proc = subprocess.Popen([self.exe, "batch"], stdin=subprocess.PIPE,
                                         stdout=subprocess.PIPE, start_new_session=True,
                                         env=self.env)
            self.pending = b""

    def run(self, scene, folder, sets, timeout):
        """The run's exit code, negative for the signal that ended the process during it, None
        after the timeout (the process is then stopped; the next run starts another)."""
        self.start()
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


class Runner:
    """Where some of a study's runs go, one after the other: a `contactlab batch` process (or a
    process per run), started with `env`."""

    def __init__(self, exe, own_process, env=None):
        self.exe = exe
        self.env = env
        self.batch = None if own_process else BatchProcess(exe, env)
        self.stopped = False
        self.own = None  # the running process of its own, if any

    def run(self, scene, folder, sets, timeout):
        """(exit code as BatchProcess.run gives it, whether the batch process ran it). After
        stop(), raises: an interrupted study starts no new process (another thread may still be
        on its way to its next run)."""
        if self.stopped:
            raise RuntimeError("the study was stopped")
        shared = self.batch is not None and self.batch.accepts(scene, folder, sets)
        if shared:
            return self.batch.run(scene, folder, sets, timeout), True
        code = run_own_process(self.exe, scene, folder, sets, timeout, self.env,
                               lambda proc: setattr(self, "own", proc))
        self.own = None
        return code, False

    def start(self):
        if self.batch:
            self.batch.start()

    def close(self):
        if self.batch:
            self.batch.close()

    def stop(self):
        self.stopped = True
        if self.batch:
            self.batch.stop()
        if self.own is not None:
            _kill(self.own)
