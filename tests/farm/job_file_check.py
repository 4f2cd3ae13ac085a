#!/usr/bin/env python3
"""Reads a job file the way its consumers do, for the tests, and prints
what they find as JSON on standard output.

  job_file_check.py sbatch FILE   the #SBATCH directives, as sbatch reads
                                  them: lines split at '\\n' only, from the
                                  top, until the first line that is neither
                                  blank nor a comment
  job_file_check.py yaml FILE     the document a YAML 1.1 reader (PyYAML, as
                                  openjd-model uses) loads from the file

Exit code 77 when PyYAML is missing (the test reports skipped), 1 when the
file cannot be read as the consumer reads it."""
import json
import sys


def sbatch_directives(data):
    directives = []
    for line in data.split(b"\n"):
        stripped = line.strip()
        if not stripped or stripped.startswith(b"#!"):
            continue
        if not stripped.startswith(b"#"):
            break
        if line.startswith(b"#SBATCH"):
            directives.append(line[len(b"#SBATCH"):].strip().decode("utf-8", "replace"))
    return directives


def main():
    mode, path = sys.argv[1], sys.argv[2]
    with open(path, "rb") as f:
        data = f.read()
    if mode == "sbatch":
        print(json.dumps(sbatch_directives(data)))
        return 0
    try:
        import yaml
    except ImportError:
        print("python3-yaml is not installed", file=sys.stderr)
        return 77
    try:
        document = yaml.safe_load(data.decode("utf-8"))
    except (UnicodeDecodeError, yaml.YAMLError) as e:
        print(f"not YAML: {e}", file=sys.stderr)
        return 1
    print(json.dumps(document))
    return 0


if __name__ == "__main__":
    sys.exit(main())
