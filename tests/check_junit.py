"""Check a JUnit report of gdsmc verify against its verdict lines.

usage: check_junit.py REPORT.xml VERDICTS.txt [REPORTS_DIR]

Every verdict line ("PASS  NAME: detail", "FAIL ...", "SKIP ...", "DIFFERS
...") must be a testcase of the report, in order, with <failure> for FAIL,
<skipped> for SKIP and <skipped> with the message "DIFFERS: detail" for
DIFFERS, and the detail as message; the counts of every testsuite and of the
whole report must be those of the lines, and of the closing summary.  With
REPORTS_DIR, each case's <case>-verdicts.csv there must hold the same
verdicts, names and details in order, and README.md each case's counts.
"""
import csv
import os
import re
import sys
import xml.etree.ElementTree as ET


def check_verdict_files(lines, reports):
    """The verdicts files and the index hold the lines' verdicts."""
    by_case = {}
    for verdict, name, detail in lines:
        by_case.setdefault(name.split(" ")[0], []).append((verdict, name, detail))
    index = open(os.path.join(reports, "README.md"), encoding="utf-8").read()
    for case, own in by_case.items():
        path = os.path.join(reports, case + "-verdicts.csv")
        rows = list(csv.DictReader(l for l in open(path, encoding="utf-8")
                                   if not l.startswith("#")))
        assert [(r["verdict"], r["name"], r["detail"]) for r in rows] == own, case
        n = {v: sum(1 for l in own if l[0] == v) for v in ("PASS", "FAIL", "SKIP", "DIFFERS")}
        row = "| %s | %d | %d | %d | %d |" % (case, n["PASS"], n["FAIL"], n["SKIP"], n["DIFFERS"])
        assert row in index, (row, index)


def main(xml_path, verdicts_path, reports=None):
    lines = [re.match(r"(PASS|FAIL|SKIP|DIFFERS)  (.*)$", l)
             for l in open(verdicts_path, encoding="utf-8").read().splitlines()]
    lines = [m.groups() for m in lines if m]   # (verdict, "NAME: DETAIL")
    summary = re.search(r"verify: (\d+) passed, (\d+) failed, (\d+) skipped"
                        r"(?:, (\d+) differ from the papers)?"
                        r"(?:, \d+ rows? refused by the solver)?\n",
                        open(verdicts_path, encoding="utf-8").read())
    root = ET.parse(xml_path).getroot()
    cases = [(suite, case) for suite in root.iter("testsuite") for case in suite.iter("testcase")]
    assert len(cases) == len(lines) > 0, (len(cases), len(lines))
    judged = []   # a name may hold ": " itself: the testcase's name splits the line
    for (verdict, text), (suite, case) in zip(lines, cases):
        name = case.get("name")
        assert text.startswith(name + ": "), (name, text)
        detail = text[len(name) + 2:]
        judged.append((verdict, name, detail))
        assert name.startswith(suite.get("name") + " "), (suite.get("name"), name)
        failure, skipped = case.find("failure"), case.find("skipped")
        kind = "FAIL" if failure is not None else "SKIP" if skipped is not None else "PASS"
        if kind == "SKIP" and skipped.get("message").startswith("DIFFERS: "):
            kind = "DIFFERS"
        assert kind == verdict, (name, kind, verdict)
        if kind != "PASS":
            message = (failure if kind == "FAIL" else skipped).get("message")
            assert message == ("DIFFERS: " if kind == "DIFFERS" else "") + detail, name
    count = {v: sum(1 for l in lines if l[0] == v) for v in ("PASS", "FAIL", "SKIP", "DIFFERS")}
    assert summary and tuple(int(g or 0) for g in summary.groups()) == (
        count["PASS"], count["FAIL"], count["SKIP"], count["DIFFERS"]), summary
    assert int(root.get("tests")) == len(lines)
    assert int(root.get("failures")) == count["FAIL"]
    assert int(root.get("skipped")) == count["SKIP"] + count["DIFFERS"]
    for suite in root.iter("testsuite"):
        own = [c for c in suite.iter("testcase")]
        assert int(suite.get("tests")) == len(own)
        assert int(suite.get("failures")) == sum(c.find("failure") is not None for c in own)
        assert int(suite.get("skipped")) == sum(c.find("skipped") is not None for c in own)
    if reports is not None:
        check_verdict_files(judged, reports)
    print("%d testcases in %d testsuites: %d passed, %d failed, %d skipped, %d differ, as the "
          "verdict lines%s" % (len(lines), len(list(root.iter("testsuite"))), count["PASS"],
                               count["FAIL"], count["SKIP"], count["DIFFERS"],
                               " and the verdicts files" if reports else ""))


if __name__ == "__main__":
    main(*sys.argv[1:4])
