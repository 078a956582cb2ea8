"""Check a JUnit report of gdsmc verify against its verdict lines.

usage: check_junit.py REPORT.xml VERDICTS.txt

Every verdict line ("PASS  NAME: detail", "FAIL ...", "SKIP ...") must be a
testcase of the report, in order, with <failure> for FAIL and <skipped> for
SKIP and the detail as message; the counts of every testsuite and of the
whole report must be those of the lines, and of the closing summary.
"""
import re
import sys
import xml.etree.ElementTree as ET


def main(xml_path, verdicts_path):
    lines = [re.match(r"(PASS|FAIL|SKIP)  (.*?): (.*)$", l)
             for l in open(verdicts_path, encoding="utf-8").read().splitlines()]
    lines = [m.groups() for m in lines if m]
    summary = re.search(r"verify: (\d+) passed, (\d+) failed, (\d+) skipped",
                        open(verdicts_path, encoding="utf-8").read())
    root = ET.parse(xml_path).getroot()
    cases = [(suite, case) for suite in root.iter("testsuite") for case in suite.iter("testcase")]
    assert len(cases) == len(lines) > 0, (len(cases), len(lines))
    for (verdict, name, detail), (suite, case) in zip(lines, cases):
        assert case.get("name") == name, (case.get("name"), name)
        assert name.startswith(suite.get("name") + " "), (suite.get("name"), name)
        failure, skipped = case.find("failure"), case.find("skipped")
        kind = "FAIL" if failure is not None else "SKIP" if skipped is not None else "PASS"
        assert kind == verdict, (name, kind, verdict)
        if kind != "PASS":
            assert (failure if kind == "FAIL" else skipped).get("message") == detail, name
    count = {v: sum(1 for l in lines if l[0] == v) for v in ("PASS", "FAIL", "SKIP")}
    assert summary and tuple(map(int, summary.groups())) == (
        count["PASS"], count["FAIL"], count["SKIP"]), summary
    assert int(root.get("tests")) == len(lines)
    assert int(root.get("failures")) == count["FAIL"]
    assert int(root.get("skipped")) == count["SKIP"]
    for suite in root.iter("testsuite"):
        own = [c for c in suite.iter("testcase")]
        assert int(suite.get("tests")) == len(own)
        assert int(suite.get("failures")) == sum(c.find("failure") is not None for c in own)
        assert int(suite.get("skipped")) == sum(c.find("skipped") is not None for c in own)
    print("%d testcases in %d testsuites: %d passed, %d failed, %d skipped, as the verdict lines"
          % (len(lines), len(list(root.iter("testsuite"))), count["PASS"], count["FAIL"],
             count["SKIP"]))


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2])
