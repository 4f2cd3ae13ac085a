#!/usr/bin/env python3
"""Runs an Open Job Description template the way a scheduler would, for the
tests: each step's tasks in order, each task in a fresh session folder of
its own, with {{Param.*}} and {{Task.Param.*}} replaced. CHUNK[INT] ranges
are cut into contiguous chunks of defaultTaskCount frames. Only what
`facet farm openjd` writes is understood; anything else is an error."""
import subprocess
import sys
import tempfile

import yaml


def expand(expression):
    """OpenJD integer range expression ("1-10", "1-9:2", "1,5,10-12")."""
    values = []
    for item in expression.split(","):
        step = 1
        if ":" in item:
            item, step_text = item.split(":")
            step = int(step_text)
        if "-" in item[1:]:
            cut = item.index("-", 1)
            first, last = int(item[:cut]), int(item[cut + 1:])
        else:
            first = last = int(item)
        values.extend(range(first, last + 1, step))
    return sorted(set(values))


def contiguous_chunks(values, size):
    """Consecutive slices of the range's values, `size` at most each."""
    return [values[i:i + size] for i in range(0, len(values), size)]


def chunk_text(chunk):
    """A chunk as a range expression: "a-b" or "a-b:s" when evenly spaced."""
    steps = {b - a for a, b in zip(chunk, chunk[1:])}
    if len(chunk) == 1:
        return str(chunk[0])
    if len(steps) == 1:
        step = steps.pop()
        return f"{chunk[0]}-{chunk[-1]}" + (f":{step}" if step != 1 else "")
    return ",".join(str(v) for v in chunk)


def substitute(word, values):
    for key, value in values.items():
        word = word.replace("{{" + key + "}}", value)
    if "{{" in word:
        sys.exit(f"unknown template variable in {word!r}")
    return word


def run(command, args, values):
    words = [substitute(command, values)] + [substitute(a, values) for a in args]
    with tempfile.TemporaryDirectory() as session:
        print("run:", " ".join(words), flush=True)
        if subprocess.call(words, cwd=session) != 0:
            sys.exit(f"task failed: {' '.join(words)}")


def main():
    template = yaml.safe_load(open(sys.argv[1]))
    assert template["specificationVersion"] == "jobtemplate-2023-09"
    assert "TASK_CHUNKING" in template.get("extensions", [])
    params = {f"Param.{p['name']}": str(p["default"]) for p in template["parameterDefinitions"]}
    done = set()
    for step in template["steps"]:
        for dependency in step.get("dependencies", []):
            assert dependency["dependsOn"] in done, "steps out of order"
        action = step["script"]["actions"]["onRun"]
        space = step.get("parameterSpace")
        if not space:
            run(action["command"], action.get("args", []), params)
        else:
            (definition,) = space["taskParameterDefinitions"]
            assert definition["type"] == "CHUNK[INT]"
            assert definition["chunks"]["rangeConstraint"] == "CONTIGUOUS"
            frames = expand(substitute(definition["range"], params))
            for chunk in contiguous_chunks(frames, definition["chunks"]["defaultTaskCount"]):
                values = dict(params)
                values[f"Task.Param.{definition['name']}"] = chunk_text(chunk)
                run(action["command"], action.get("args", []), values)
        done.add(step["name"])


main()
