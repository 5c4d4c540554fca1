"""Counts gtest/rostest JUnit results under a catkin test_results folder.

Prints one line per failed or errored test case, followed by the first lines of its failure message (the
assertion and what it printed, so a CI log names the cause), then a last line "PASSED FAILED" (two integers).
A result file that is missing its test cases (a crashed test binary or a rostest that never connected)
counts as one failure, so a broken test can never look green.
"""
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

MAX_MESSAGE_LINES = 20
root = Path(sys.argv[1])
passed = failed = 0
for xml in sorted(root.rglob("*.xml")):
    try:
        tree = ET.parse(xml)
    except ET.ParseError as e:
        print(f"FAILED {xml.name}: unreadable result file ({e})")
        failed += 1
        continue
    cases = list(tree.iter("testcase"))
    if not cases:
        print(f"FAILED {xml.name}: no test cases recorded")
        failed += 1
        continue
    for case in cases:
        bad = case.find("failure") is not None or case.find("error") is not None
        skipped = case.find("skipped") is not None or case.get("status") == "notrun"
        if skipped:
            continue
        if bad:
            failed += 1
            print(f"FAILED {xml.name}: {case.get('classname')}.{case.get('name')}")
            for tag in ("failure", "error"):
                for node in case.findall(tag):
                    text = (node.text or node.get("message") or "").strip()
                    lines = text.splitlines()
                    for line in lines[:MAX_MESSAGE_LINES]:
                        print(f"    {line}")
                    if len(lines) > MAX_MESSAGE_LINES:
                        print(f"    ... ({len(lines) - MAX_MESSAGE_LINES} more lines in {xml})")
        else:
            passed += 1
print(passed, failed)
