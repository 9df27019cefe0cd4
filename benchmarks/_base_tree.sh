# SPDX-License-Identifier: EPL-2.0
# Sourced by the benchmarks that compare this tree with a base commit (monitor_throughput.sh, vepl_throughput.sh).
#
# in_base_tree REF LOG COMMAND...: runs COMMAND (a function of the caller's, say) in a temporary detached worktree
# of REF, its output into LOG, then removes the worktree; returns 1 with a line naming LOG when COMMAND fails.
# Nothing is installed into the local Maven repository: it keeps this tree's artifacts.
in_base_tree() {
  local ref="$1" log="$2" tree status=0
  shift 2
  tree="$(mktemp -d)/base"
  git -C "$ROOT" worktree add -q --detach "$tree" "$ref"
  (cd "$tree" && "$@") >"$log" 2>&1 || status=$?
  git -C "$ROOT" worktree remove --force "$tree" >/dev/null 2>&1 || true
  if (( status )); then
    echo "   the base does not build: $log"
    return 1
  fi
}
