#!/usr/bin/env bash
# The render farm workflow on a real Slurm cluster (docs/farm.md): a one-host
# cluster is started here, a 48-frame scene is rendered as 6 array tasks and
# merged, then one task is killed mid-run, resubmitted alone and merged
# again. Each result must list the same files with the same hashes as one
# process rendering the whole scene. The daemons started here are stopped,
# by their process ids, whatever happens.
#
#   scripts/slurm-test.sh [FACET]     FACET: the facet program (default build/facet)
#
# Called by the test suite (ctest -R slurm) and so by CI.
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
facet=$(readlink -f "${1:-$root/build/facet}")
work=$(mktemp -d /tmp/facet-slurm-test.XXXXXX)
cluster="$work/cluster"

submitter=""
finish() {
    local code=$?
    # A submitter still waiting would wait forever once the daemons stop.
    if [ -n "$submitter" ]; then pkill -P "$submitter" 2>/dev/null || true; kill "$submitter" 2>/dev/null || true; fi
    "$root/scripts/slurm-cluster.sh" stop "$cluster" || code=1
    if pgrep -f "$cluster/slurm.conf" >/dev/null; then
        echo "slurm-test: daemons of this cluster are still running" >&2
        code=1
    fi
    if [ "$code" -ne 0 ]; then
        echo "slurm-test: FAILED; logs:" >&2
        tail -n 20 "$cluster"/*.log "$work"/slurm-*.out 2>/dev/null >&2 || true
    fi
    rm -rf "$work"
    exit "$code"
}
trap finish EXIT

fail() {
    echo "slurm-test: $*" >&2
    exit 1
}

eval "$("$root/scripts/slurm-cluster.sh" start "$cluster")"
[ -n "${SLURM_CONF:-}" ] || fail "the cluster script printed no SLURM_CONF"

# A scene big enough that a task runs for a second or more even on a fast
# machine, so that one can be killed mid-run.
cd "$work"
cat > spin.yaml <<'YAML'
output: { size: [1280, 720], frames: "1-48", passes: [color, depth], formats: [png, exr] }
camera: { orbit: { radius: 4, turns: 1 } }
lights: [ { type: directional, direction: [-1, -1, -1] } ]
objects: [ { primitive: { type: torus, segments: 256, rings: 64 }, material: { color: [0.8, 0.4, 0.2] } } ]
YAML

# path -> sha256 of every file a manifest lists, sorted.
listed() {
    python3 -c '
import json, sys
m = json.load(open(sys.argv[1]))
for f in sorted(m["files"], key=lambda f: f["path"]):
    print(f["path"], f["sha256"])' "$1"
}

"$facet" render spin.yaml -o single --threads 2 -q
listed single/spin/manifest.json > single.txt
[ "$(wc -l < single.txt)" -eq 192 ] || fail "the single render lists $(wc -l < single.txt) files, not 192"

echo "slurm-test: the whole job: 6 array tasks and the merge (bash job.sh --wait)"
"$facet" farm slurm spin.yaml --chunks 6 --cpus 1 --time 10:00 -o farm --script job.sh -q
bash job.sh --wait
[ -f farm/spin/manifest.json ] || fail "no merged manifest"
listed farm/spin/manifest.json > farm.txt
cmp -s single.txt farm.txt || fail "the merged manifest differs from the single render's"
[ -z "$(ls farm/spin/manifest.part-* 2>/dev/null)" ] || fail "partial manifests left after the merge"
hosts=$(python3 -c 'import json; print(len(json.load(open("farm/spin/manifest.json"))["timings"]["parts"]))')
[ "$hosts" -eq 6 ] || fail "the merged manifest records $hosts parts, not 6"

echo "slurm-test: one task killed mid-run, then resubmitted alone"
# One task at a time, so that task 3 runs alone and is easy to catch.
"$facet" farm slurm spin.yaml --chunks 6 --cpus 1 --max-running 1 -o killed --script job2.sh -q
(
    code=0
    bash job2.sh --wait > submit2.log 2>&1 || code=$?
    echo "$code" > submit2.code
) &
submitter=$!
# Task 3 renders frames 25-32. It is killed once its journal records an
# image: it is then mid-run, whatever the machine's speed. The journal's
# name ends in the process id.
victim=""
for _ in $(seq 1 3000); do
    journal=$(find killed/spin -maxdepth 1 -name '.manifest.part-0025-0032.json.*.journal' 2>/dev/null | head -n 1 || true)
    if [ -n "$journal" ] && [ "$(wc -l < "$journal")" -ge 2 ]; then
        victim=${journal%.journal}
        victim=${victim##*.}
        break
    fi
    sleep 0.02
done
[ -n "$victim" ] || fail "task 3 never started writing"
kill -9 "$victim"
echo "slurm-test: killed task 3 (pid $victim) after it wrote $(($(wc -l < "$journal") - 1)) images"
wait "$submitter"
submitter=""
code=$(cat submit2.code)
cat submit2.log
[ "$code" -ne 0 ] || fail "bash job2.sh --wait succeeded although task 3 was killed"
grep -q "chunks that did not complete: 3;" submit2.log || fail "the failed chunk was not named"
[ ! -f killed/spin/manifest.json ] || fail "a merged manifest exists although task 3 failed"
[ ! -f killed/spin/manifest.part-0025-0032.json ] || fail "the killed task wrote its manifest"

bash job2.sh --tasks 3 --wait
[ -f killed/spin/manifest.json ] || fail "no merged manifest after the resubmitted task"
listed killed/spin/manifest.json > killed.txt
cmp -s single.txt killed.txt || fail "after the resubmission the manifest differs from the single render's"
# The resubmitted task kept what the killed one had written.
log=$(ls -t slurm-*_3.out | head -n 1)
grep -q "already written" "$log" || fail "the resubmitted task rendered everything again ($log)"
leftovers=$(find killed/spin farm/spin -name '.*')
[ -z "$leftovers" ] || fail "temporary files, journals or locks were left: $leftovers"

echo "slurm-test: the script submitted with sbatch instead of bash"
"$facet" farm slurm spin.yaml --chunks 3 --cpus 1 --frames 1-12 -o submitted --script job3.sh -q
sbatch --wait job3.sh > /dev/null
for _ in $(seq 1 600); do
    [ -z "$(squeue -h)" ] && break
    sleep 0.2
done
[ -f submitted/spin/manifest.json ] || fail "sbatch job3.sh did not complete the job"
listed submitted/spin/manifest.json > submitted.txt
grep -E '\.00(0[1-9]|1[0-2])\.' single.txt | cmp -s - submitted.txt ||
    fail "frames 1-12 submitted with sbatch differ from the single render's"
echo "slurm-test: ok"
