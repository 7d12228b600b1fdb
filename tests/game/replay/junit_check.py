"""Reads a JUnit XML report with a real XML parser and prints what it holds as JSON.

Usage: python3 junit_check.py REPORT.xml
A report that is not well-formed XML ends with an error (exit 1), so the test that runs this fails.
Prints {"suites": [...], "cases": [...]}: each suite's name and counts, each testcase's attributes
and its failure, error and system-out (type, message, text), for the test to compare.
"""
import json
import sys
import xml.etree.ElementTree as ET


def outcome(case, tag):
    element = case.find(tag)
    if element is None:
        return None
    return {"type": element.get("type"), "message": element.get("message"), "text": element.text or ""}


def main():
    root = ET.parse(sys.argv[1]).getroot()
    if root.tag != "testsuites":
        sys.exit("the root element is <%s>, expected <testsuites>" % root.tag)
    suites, cases = [], []
    for suite in root.findall("testsuite"):
        suites.append({key: suite.get(key) for key in ("name", "tests", "failures", "errors", "skipped", "time")})
        suites[-1]["properties"] = {p.get("name"): p.get("value") for p in suite.findall("properties/property")}
        for case in suite.findall("testcase"):
            entry = {key: case.get(key) for key in ("classname", "name", "file", "time")}
            float(entry["time"])  # a number, or this raises
            entry["failure"] = outcome(case, "failure")
            entry["error"] = outcome(case, "error")
            out = case.find("system-out")
            entry["out"] = "" if out is None else out.text or ""
            cases.append(entry)
    json.dump({"suites": suites, "cases": cases}, sys.stdout)


main()
