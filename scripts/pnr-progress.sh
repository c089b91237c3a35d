# pnr-progress.sh -- sourced by scripts/pnr.sh, pnr-seeds.sh and
# bitstream.sh: progress lines while nextpnr runs (a full LFE5U-85F
# places and routes for half an hour to three hours, silent until then).
#
# pnr_progress_start PREFIX PATH: every PNR_PROGRESS seconds (default 60;
#   0 for none) a line "PREFIX: H:MM:SS elapsed; PHASE" with the phase of
#   the nextpnr log at PATH, or, when PATH is a folder, with the phase of
#   each seed registered there (scripts/pnr-phase.py --watch).  The
#   watcher runs out of the caller's job table, so that the caller's
#   `wait -n` waits for its own jobs only.  Exits 2 on a bad PNR_PROGRESS.
# pnr_progress_stop: ends the watcher; call it from the caller's EXIT trap
#   too (the watcher also ends by itself once its caller, $$, has gone).
pnr_watcher=
pnr_progress_start() {
  local every=${PNR_PROGRESS:-60}
  [[ "$every" =~ ^[0-9]+$ ]] ||
    { echo "$(basename "$0"): bad PNR_PROGRESS '$every' (seconds, 0 for none)" >&2; exit 2; }
  [ "$every" -gt 0 ] || return 0
  python3 "$(dirname "${BASH_SOURCE[0]}")/pnr-phase.py" --watch "$every" "$1" "$2" $$ &
  pnr_watcher=$!
  disown "$pnr_watcher"
}
pnr_progress_stop() {
  [ -z "$pnr_watcher" ] || kill "$pnr_watcher" 2>/dev/null || true
  pnr_watcher=
}
