#!/usr/bin/env python3
"""Concurrent starts of contactlab never kill one another, and leave nothing in TMPDIR.

Usage: check_concurrent_starts.py CONTACTLAB SCENE WORKDIR [STREAMS] [STARTS_PER_STREAM]

Started without mpirun, contactlab is an isolated MPI singleton. Open MPI puts every isolated
singleton in job family 0, hence in one shared session directory under TMPDIR; a process
ending removed it while another was starting in it, and that one aborted in MPI_Init ("A call
to mkdir was unable to create the desired directory"). STREAMS threads each start
`contactlab validate SCENE` STARTS_PER_STREAM times back to back, all with one private TMPDIR
(so the test shares no path with any other process on the machine). Every start must exit 0;
while they run, TMPDIR must hold only per-process directories (contactlab-mpi-*), never Open
MPI's shared one (ompi.<host>.<uid>: the race is rare, its cause is not); afterwards it must be
empty: each process removes its own.
"""
import os
import shutil
import subprocess
import sys
import threading


def main():
    app, scene, work = sys.argv[1:4]
    streams = int(sys.argv[4]) if len(sys.argv) > 4 else 6
    starts = int(sys.argv[5]) if len(sys.argv) > 5 else 15
    shutil.rmtree(work, ignore_errors=True)
    tmp = os.path.join(work, "tmp")
    os.makedirs(tmp)
    env = dict(os.environ, TMPDIR=tmp, OPENBLAS_NUM_THREADS="1")
    env.pop("OMPI_MCA_orte_tmpdir_base", None)
    if os.environ.get("CONCURRENT_STARTS_SHARED"):  # the old behaviour, to see the test fail
        env["OMPI_MCA_orte_tmpdir_base"] = tmp
    failures = []
    lock = threading.Lock()

    def stream(k):
        for i in range(starts):
            r = subprocess.run([app, "validate", scene], env=env, capture_output=True,
                               text=True, timeout=300)
            if r.returncode != 0:
                with lock:
                    failures.append((k, i, r.returncode, (r.stderr or r.stdout)[-600:]))

    shared = set()
    done = threading.Event()

    def watch():  # what appears in TMPDIR while the processes run
        while not done.is_set():
            for name in os.listdir(tmp):
                if not name.startswith("contactlab-mpi-"):
                    shared.add(name)
            done.wait(0.005)

    watcher = threading.Thread(target=watch)
    watcher.start()
    threads = [threading.Thread(target=stream, args=(k,)) for k in range(streams)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    done.set()
    watcher.join()
    total = streams * starts
    for k, i, code, text in failures[:3]:
        print(f"stream {k} start {i}: exit {code}\n{text}")
    left = os.listdir(tmp)
    print(f"{total} starts in {streams} streams: {len(failures)} failed; "
          f"shared directories seen in TMPDIR: {sorted(shared) if shared else 'none'}; "
          f"left in TMPDIR: {left if left else 'nothing'}")
    if failures or left or shared:
        sys.exit(1)
    shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
