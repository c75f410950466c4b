#!/usr/bin/env python3
"""Checks a `dcel diff --report` file against docs/diff-report.schema.json
(jsonschema, Debian's python3-jsonschema) and that a --junit file is XML with
one test case per failure plus one for the run.

    validate_report.py REPORT.json [JUNIT.xml]
"""
import json
import os
import sys
import xml.etree.ElementTree as ET

import jsonschema

HERE = os.path.dirname(os.path.abspath(__file__))
SCHEMA = os.path.join(HERE, "..", "..", "docs", "diff-report.schema.json")


def main():
    with open(SCHEMA) as f:
        schema = json.load(f)
    with open(sys.argv[1]) as f:
        report = json.load(f)
    jsonschema.Draft202012Validator.check_schema(schema)
    jsonschema.validate(report, schema, cls=jsonschema.Draft202012Validator)
    line = "report valid: %d failures, schema docs/diff-report.schema.json" % len(report["failures"])
    if len(sys.argv) > 2:
        root = ET.parse(sys.argv[2]).getroot()
        cases = root.findall(".//testcase")
        failures = root.findall(".//testcase/failure")
        if len(cases) != len(report["failures"]) + 1 or len(failures) != len(report["failures"]):
            sys.exit("junit: %d test cases and %d failures for %d failures in the report"
                     % (len(cases), len(failures), len(report["failures"])))
        line += ", junit: %d test cases, %d failures" % (len(cases), len(failures))
    print(line)


if __name__ == "__main__":
    main()
