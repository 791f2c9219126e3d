#!/usr/bin/env python3
"""The validation report in a real browser: headless Chromium driven by Selenium (Debian's
chromium, chromium-driver and python3-selenium).

Builds a report from real runs of the given rodvv binary (8 passing cases of two families, and one
case whose levels all fail under a tiny --level-budget), opens index.html from disk (the page must
work offline, as a file) and checks that
  - it loads without console errors (SEVERE entries of the browser log),
  - the overview figure is rendered with one point per gate that has a margin, and the failing
    case's gates lead the "needs attention" table,
  - the family, status and name filters hide and show cases, contents entries, overview points and
    table rows, and empty family blocks disappear,
  - a query string (?status=fail) sets the filters on load.

Exit 77 (CTest: skipped) when the browser stack is missing, unless RODVV_REQUIRE_BROWSER=1
(scripts/test.sh installs it and sets that, so CI cannot skip silently).

usage: test_report_browser.py <rodvv executable>
"""
import os
import shutil
import subprocess
import sys
import tempfile

CHROMIUM = "/usr/bin/chromium"
CHROMEDRIVER = "/usr/bin/chromedriver"
PASSING = ["pendulum/libration-30", "elastica/pinned-pinned-10"]
FAILING = "eulerian1d/standing-wave"

failures = []


def check(condition, what):
    if not condition:
        failures.append(what)
        print("FAIL:", what)


def skip_or_fail(why):
    if os.environ.get("RODVV_REQUIRE_BROWSER") == "1":
        print(f"browser test required (RODVV_REQUIRE_BROWSER=1) but {why}")
        sys.exit(1)
    print(f"skipped: {why} (scripts/setup.sh chromium chromium-driver python3-selenium)")
    sys.exit(77)


def run(cmd, ok_codes=(0,)):
    proc = subprocess.run(cmd, capture_output=True, text=True)
    if proc.returncode not in ok_codes:
        print(" ".join(cmd), "->", proc.returncode, proc.stderr[-2000:])
        sys.exit(1)
    return proc


def build_report(rodvv, work):
    results = os.path.join(work, "results")
    os.makedirs(results)
    run([rodvv, "run", *PASSING, "--json", os.path.join(results, "passing.json")])
    # Every level over a 1 microsecond budget: a genuinely failing case (exit 1), gates unmeasured.
    run([rodvv, "run", FAILING, "--level-budget", "1e-6", "--json", os.path.join(results, "failing.json")],
        ok_codes=(1,))
    out = os.path.join(work, "report")
    run([rodvv, "report", "--from", results, "--out", out, "--no-plots"], ok_codes=(1,))
    return os.path.join(out, "index.html")


def start_browser(profile):
    from selenium import webdriver
    from selenium.webdriver.chrome.service import Service

    options = webdriver.ChromeOptions()
    options.binary_location = CHROMIUM
    # The flags of a closed-network sandbox: no background connections, no first-run UI.
    for flag in ("--headless=new", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
                 "--disable-background-networking", "--disable-component-update", "--disable-sync",
                 "--window-size=1280,1000", f"--user-data-dir={profile}"):
        options.add_argument(flag)
    options.set_capability("goog:loggingPrefs", {"browser": "ALL"})
    return webdriver.Chrome(service=Service(executable_path=CHROMEDRIVER), options=options)


def visible(driver, selector):
    from selenium.webdriver.common.by import By
    return [e for e in driver.find_elements(By.CSS_SELECTOR, selector) if e.is_displayed()]


def hidden_count(driver, selector):
    """Elements hidden by the filters (SVG points are not 'displayed' by Selenium's rules either
    way, so the filters' class is what is checked for them)."""
    from selenium.webdriver.common.by import By
    return len(driver.find_elements(By.CSS_SELECTOR, selector + ".filtered-out"))


def main(argv):
    if len(argv) != 2:
        print(__doc__)
        return 2
    rodvv = argv[1]
    for path in (CHROMIUM, CHROMEDRIVER):
        if not os.path.exists(path):
            skip_or_fail(f"{path} is not installed")
    try:
        import selenium  # noqa: F401
    except ImportError:
        skip_or_fail("python3-selenium is not installed")
    from selenium.webdriver.common.by import By
    from selenium.webdriver.support.ui import Select

    work = tempfile.mkdtemp(prefix="rodvv-browser-")
    try:
        index = build_report(rodvv, work)
        url = "file://" + index
        driver = start_browser(os.path.join(work, "profile"))
        try:
            driver.get(url)
            severe = [e for e in driver.get_log("browser") if e.get("level") == "SEVERE"]
            check(not severe, f"no console errors on load (got {severe})")

            # The overview: one point per gate with a margin, from both families.
            figure = driver.find_elements(By.ID, "overview-figure")
            check(len(figure) == 1 and figure[0].is_displayed(), "the overview figure is displayed")
            points = driver.find_elements(By.CSS_SELECTOR, "#overview-figure a.point")
            check(len(points) >= 30, f"the overview has a point per measured gate (got {len(points)})")
            check(figure[0].size["width"] > 600, f"the overview is full width (got {figure[0].size})")
            # The failing case's gates lead the attention table.
            rows = driver.find_elements(By.CSS_SELECTOR, "#at-a-glance tr.filterable")
            check(rows and rows[0].get_attribute("data-name") == FAILING,
                  "the failing case's gates come first in the attention table")
            check(rows and "FAIL" in rows[0].text, "its first row says FAIL")

            cases = driver.find_elements(By.CSS_SELECTOR, "section.case")
            total = len(cases)
            check(total == 9, f"9 cases on the page (got {total})")
            count = driver.find_element(By.ID, "filter-count")
            check(count.text == f"showing {total} of {total} cases", f"count before filtering: {count.text!r}")

            # Status filter: only the failing case remains, everywhere.
            Select(driver.find_element(By.ID, "filter-status")).select_by_value("fail")
            shown = visible(driver, "section.case")
            check([s.get_attribute("data-name") for s in shown] == [FAILING], "status=fail shows the failing case only")
            check(count.text == f"showing 1 of {total} cases", f"count under status=fail: {count.text!r}")
            check(len(visible(driver, "nav.toc li.filterable")) == 1, "one contents entry under status=fail")
            check(hidden_count(driver, "#overview-figure a.point") == len(points),
                  "every overview point belongs to a passing case (the failing one measured nothing): all hidden")
            family_blocks = visible(driver, "div.family-block")
            check(len(family_blocks) == 1, f"only the failing case's family block is shown (got {len(family_blocks)})")

            # Family filter (status back to all): only pendulum cases and points.
            Select(driver.find_element(By.ID, "filter-status")).select_by_value("")
            Select(driver.find_element(By.ID, "filter-family")).select_by_value("pendulum")
            shown = visible(driver, "section.case")
            check(len(shown) == 6 and all(s.get_attribute("data-family") == "pendulum" for s in shown),
                  f"family=pendulum shows its 6 cases (got {len(shown)})")
            hidden_points = driver.find_elements(By.CSS_SELECTOR, "#overview-figure a.point.filtered-out")
            check(hidden_points and all(p.get_attribute("data-family") != "pendulum" for p in hidden_points),
                  "family=pendulum hides exactly the other families' points")

            # Name filter, typed: "verlet" within pendulum.
            name = driver.find_element(By.ID, "filter-name")
            name.send_keys("verlet")
            shown = visible(driver, "section.case")
            check([s.get_attribute("data-name") for s in shown] == ["pendulum/libration-30/stormer-verlet"],
                  f"name=verlet shows the Stoermer-Verlet case (got {[s.get_attribute('data-name') for s in shown]})")
            name.clear()
            name.send_keys("x")  # clear() fires no input event; a keystroke and a backspace do
            name.send_keys("\b")
            Select(driver.find_element(By.ID, "filter-family")).select_by_value("")
            check(count.text == f"showing {total} of {total} cases", f"count after clearing: {count.text!r}")

            # A linked, filtered view.
            driver.get(url + "?status=fail")
            check(len(visible(driver, "section.case")) == 1, "?status=fail filters on load")
            severe = [e for e in driver.get_log("browser") if e.get("level") == "SEVERE"]
            check(not severe, f"no console errors after filtering (got {severe})")
        finally:
            driver.quit()
    finally:
        shutil.rmtree(work, ignore_errors=True)

    if failures:
        print(f"{len(failures)} check(s) failed")
        return 1
    print("report in the browser: all checks passed")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
