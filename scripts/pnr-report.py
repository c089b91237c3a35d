#!/usr/bin/env python3
"""pnr-report.py REPORT.json NAME DEVICE TARGET_MHZ [CSV] -- summarise a
nextpnr --report file: utilisation, Fmax of the clock and its critical
path (cells along it, logic and routing delay, the modules it crosses).
The path is shown as the RTL nets it runs along.  Prints a few lines;
with CSV, appends one row
name,device,luts,ffs,dsps,brams,fmax_mhz,target_mhz,levels,logic_ns,routing_ns,from,to
"""
import json
import re
import sys


def used(util, *names):
    return sum(util.get(n, {}).get("used", 0) for n in names)


def avail(util, *names):
    return sum(util.get(n, {}).get("available", 0) for n in names)


def main():
    rep_path, name, device, target = sys.argv[1:5]
    csv_path = sys.argv[5] if len(sys.argv) > 5 else None
    with open(rep_path) as f:
        rep = json.load(f)
    util = rep.get("utilization", {})
    if "TRELLIS_COMB" in util:        # ECP5
        luts = ("TRELLIS_COMB",); ffs = ("TRELLIS_FF",)
        dsps = ("MULT18X18D",); brams = ("DP16KD",)
    else:                             # iCE40
        luts = ("ICESTORM_LC",); ffs = ()
        dsps = ("ICESTORM_DSP",); brams = ("ICESTORM_RAM",)
    n_lut, n_dsp, n_bram = used(util, *luts), used(util, *dsps), used(util, *brams)
    print(f"  {name} on {device}: LUTs {n_lut}/{avail(util, *luts)}"
          + (f"  FFs {used(util, *ffs)}/{avail(util, *ffs)}" if ffs else "")
          + f"  DSPs {n_dsp}/{avail(util, *dsps)}  BRAMs {n_bram}/{avail(util, *brams)}")
    n_ff = used(util, *ffs) if ffs else -1

    fmax = rep.get("fmax", {})
    # The processor's clock domain (nextpnr names it after the clock net).
    clk = next((k for k in fmax if "clk" in k), None)
    if clk is None:
        print("  no clock domain in the report"); sys.exit(1)
    achieved = fmax[clk]["achieved"]
    verdict = "meets" if achieved >= float(target) else "MISSES"
    print(f"  Fmax {achieved:.1f} MHz ({verdict} the {float(target):.0f} MHz target)")

    path = None
    for cp in rep.get("critical_paths", []):
        # register to register within the clock domain (not <async> I/O)
        if clk in cp.get("from", "") and clk in cp.get("to", ""):
            path = cp["path"]; break
    levels = logic = routing = 0.0
    src = dst = "?"
    if path:
        # Cells after synthesis mostly have generated names; the nets the
        # path runs along keep the RTL's names (hierarchy.signal[bit]).
        nets = []
        for seg in path:
            if seg["type"] == "routing":
                routing += seg["delay"]
                net = seg.get("net", "")
                leaf = net.split(".")[-1]
                if net and not net.startswith("$") and not leaf.startswith("$"):
                    # drop what autoname appends (_LUT4_Z..., $CCU2_...)
                    base = re.split(r"_(?:LUT4|L6MUX21|PFUMX|CCU2C|TRELLIS|DP16KD|MULT18X18D)"
                                    r"|\$|\[", net)[0]
                    if not nets or nets[-1] != base:
                        nets.append(base)
            else:
                logic += seg["delay"]
                if seg["type"] == "logic":
                    levels += 1
        src = path[0]["from"]["cell"]
        dst = path[-1]["to"]["cell"]
        print(f"  critical path: {logic + routing:.2f} ns = {logic:.2f} ns logic "
              f"({int(levels)} cells) + {routing:.2f} ns routing")
        print(f"    from cell {src}\n    to cell   {dst}\n    along the RTL nets:")
        line = "    "
        for i, n in enumerate(nets):
            item = n + (" -> " if i + 1 < len(nets) else "")
            if len(line) + len(item) > 100:
                print(line.rstrip()); line = "      "
            line += item
        print(line.rstrip())
    if csv_path:
        with open(csv_path, "a") as f:
            f.write(f"{name},{device},{n_lut},{n_ff},{n_dsp},{n_bram},{achieved:.1f},{target},"
                    f"{int(levels)},{logic:.2f},{routing:.2f},{src},{dst}\n")


if __name__ == "__main__":
    main()
