"""PASS/FAIL lines shared by the outside checks in this folder (ema_check.py, tir_check.py,
py_check.py): each criterion prints one line with its measured figure; the script's exit status
is 1 when any failed. Standard library only."""


class Report:
    def __init__(self):
        self.failures = 0

    def check(self, label, ok, figure):
        """One criterion: PASS/FAIL, what is checked, the measured figure."""
        self.failures += 0 if ok else 1
        print(f"  {'PASS' if ok else 'FAIL'}  {label}: {figure}")
