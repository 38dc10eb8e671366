"""The pass/fail bookkeeping the check scripts share: each check prints "ok" or "FAIL" with its
sentence and remembers the failures; the script exits 1 when there is any. Imported by scripts
in tests/app and tests/verification (they put tests/ on sys.path)."""


class Checklist:
    def __init__(self):
        self.failures = []

    def check(self, what, ok):
        """Records one check; returns ok so that a caller can skip what depends on it."""
        print(("ok   " if ok else "FAIL ") + what)
        if not ok:
            self.failures.append(what)
        return ok
