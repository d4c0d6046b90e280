"""Shared by every pytest run under Testing/: where every prerequisite must be present (the
environment variable PHONGVTK_NO_SKIPS set and not "0", as scripts/test.sh sets it on
ParaView's flavour, whose set-up installs Xvfb, MPI, matplotlib and CGAL's data) a skipped test
fails, naming what it missed, instead of leaving the run green."""
import os

import pytest


def no_skips():
    return os.environ.get("PHONGVTK_NO_SKIPS", "") not in ("", "0")


@pytest.hookimpl(hookwrapper=True)
def pytest_runtest_makereport(item, call):
    outcome = yield
    report = outcome.get_result()
    if report.skipped and not hasattr(report, "wasxfail") and no_skips():
        reason = report.longrepr[2] if isinstance(report.longrepr, tuple) else report.longrepr
        report.outcome = "failed"
        report.longrepr = ("a prerequisite is missing where none may be (PHONGVTK_NO_SKIPS is "
                           f"set): {reason}")
