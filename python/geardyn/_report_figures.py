"""Interactive (plotly.js) figures of a result folder for the HTML report: plain dicts in
plotly's JSON figure format ({"data": traces, "layout": ...}), built from the same CSV tables
as the PNG plots. Gear-pair commands here; rotors, trains and sweeps in _report_figures_rotor."""

import csv

from ._tables import _read_columns, log_floor, mesh_frequency_per_rpm, read_rows, stability_runs

UM = "µm"
_COLOURS = ["#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f",
            "#bcbd22", "#17becf"]


def figure(name, caption, data, layout, height=480):
    """One report figure: a heading, a caption and plotly's data and layout."""
    return {"name": name, "caption": caption, "data": data, "layout": layout, "height": height}


def axes_layout(title, x_title, y_title, y_log=False, **extra):
    layout = {"title": {"text": title, "font": {"size": 14}},
              "xaxis": {"title": {"text": x_title}, "zeroline": False},
              "yaxis": {"title": {"text": y_title}, "zeroline": False},
              "hovermode": "closest", "margin": {"t": 60, "r": 20}}
    if y_log:
        layout["yaxis"]["type"] = "log"
    layout.update(extra)
    return layout


def rows_layout(title, x_title, y_titles, gap=0.07, share_x=True):
    """Stacked rows sharing (by default) one x axis: axes x, x2, ... and y, y2, ...."""
    n = len(y_titles)
    height = (1.0 - gap * (n - 1)) / n
    layout = {"title": {"text": title, "font": {"size": 14}}, "hovermode": "closest",
              "margin": {"t": 60, "r": 20}}
    for k, y_title in enumerate(y_titles):
        suffix = "" if k == 0 else str(k + 1)
        top = 1.0 - k * (height + gap)
        layout["yaxis" + suffix] = {"title": {"text": y_title}, "domain": [max(0.0, top - height), top],
                                    "anchor": "x" + suffix}
        x_axis = {"anchor": "y" + suffix}
        if share_x and k:
            x_axis["matches"] = "x"
        if k == n - 1 or not share_x:
            x_axis["title"] = {"text": x_title}
        else:
            x_axis["showticklabels"] = False
        layout["xaxis" + suffix] = x_axis
    return layout


def line(x, y, name, row=0, **extra):
    trace = {"type": "scatter", "mode": "lines", "x": list(x), "y": list(y), "name": name}
    if row:
        trace["xaxis"], trace["yaxis"] = f"x{row + 1}", f"y{row + 1}"
    trace.update(extra)
    return trace


def markers(x, y, name, symbol="circle-open", row=0, **extra):
    extra.setdefault("marker", {"symbol": symbol, "size": 8})
    return line(x, y, name, row, mode="markers", **extra)


def log_range(values, dynamic_range=1e-6):
    """A log axis range [log10 low, log10 high] from the data: at most 1/dynamic_range below the
    peak (numerical zeros would otherwise stretch it over many decades)."""
    import math

    low = log_floor(values, dynamic_range)
    if low is None:
        return None
    high = max(v for v in values if v > 0 and math.isfinite(v))
    return [math.log10(low) - 0.1, math.log10(high) + 0.3]


def _title(summary, fallback):
    return summary.get("config", {}).get("title") or fallback


def geometry(folder, summary):
    profiles = {}
    with open(folder / "tooth_profiles.csv", newline="") as handle:
        for row in csv.DictReader(handle):
            xs, ys = profiles.setdefault(row["member"], ([], []))
            xs.append(1e3 * float(row["x_m"]))
            ys.append(1e3 * float(row["y_m"]))
    data = []
    for member, (xs, ys) in profiles.items():
        whole_x = [-x for x in xs] + list(reversed(xs))[1:]
        whole_y = ys + list(reversed(ys))[1:]
        data.append(line(whole_x, whole_y, f"{member} tooth"))
    layout = axes_layout(f"{_title(summary, 'gear geometry')}: one tooth of each member", "x [mm]", "y [mm]")
    layout["yaxis"]["scaleanchor"] = "x"
    return [figure("Tooth profiles", "One tooth of each member in its own frame (centre at the origin).",
                   data, layout)]


def stiffness(folder, summary):
    table = _read_columns(folder / "mesh_stiffness.csv")
    phase = table["mesh_fraction"]
    primary = summary["results"]["mesh_stiffness"]["model"]
    has_ste = "ste_transverse_m" in table
    layout = rows_layout(f"{_title(summary, 'mesh stiffness')}", "mesh phase [mesh periods]",
                         ["mesh stiffness [N/m]"] + (["loaded STE [µm]"] if has_ste else []))
    data = [line(phase, table["k_total_transverse_n_per_m"], primary, line={"width": 2.5})]
    for name in table:
        if name.startswith("k_pair_"):
            data.append(line(phase, table[name], f"{primary}, pair {name.split('_')[2]}", line={"dash": "dash"}))
        elif name.startswith("k_") and name != "k_total_transverse_n_per_m":
            data.append(line(phase, table[name], name[2:].replace("_transverse_n_per_m", "")))
    if has_ste:
        data.append(line(phase, [1e6 * v for v in table["ste_transverse_m"]], "loaded STE", row=1, line={"color": "black"}))
    return [figure("Mesh stiffness", "Mesh stiffness of every model over one mesh period"
                   + (" and the loaded static transmission error." if has_ste else "."), data, layout,
                   640 if has_ste else 480)]


def simulate(folder, summary):
    table = _read_columns(folder / "time_response.csv")
    si = summary["results"]["model"]["units"] == "SI"
    layout = rows_layout(_title(summary, "gear-pair time response"), "t [s]" if si else "t1 = ω_n t [-]",
                         [f"y = x - e [{UM if si else '-'}]", f"transverse mesh force [{'N' if si else '-'}]"])
    t, u = table["t_s" if si else "t_nondim"], "" if si else "nondim"
    data = [line(t, [v * (1e6 if si else 1.0) for v in table["y_transverse_" + (u or "m")]], "relative deflection y"),
            line(t, table["mesh_force_transverse_" + (u or "n")], "mesh force", row=1, line={"color": _COLOURS[3]})]
    return [figure("Time history", "Steady periods of the Newmark time response.", data, layout, 600)]


def stats(folder, summary):
    table = _read_columns(folder / "histogram.csv")
    centres = [(lo + hi) / 2 for lo, hi in zip(table["ratio_low"], table["ratio_high"])]
    widths = [hi - lo for lo, hi in zip(table["ratio_low"], table["ratio_high"])]
    data = [{"type": "bar", "x": centres, "y": table["count"], "width": widths, "name": "samples"}]
    return [figure("Monte Carlo histogram", "Mean excitation ratio R of the random samples.", data,
                   axes_layout(_title(summary, "Monte Carlo"), "mean excitation ratio R [-]", "samples"))]


def forced_response_traces(rows, unit, per_rpm):
    """HBM sweeps up and down: stable runs solid, unstable dashed, one legend entry each."""
    data = []
    colours = {"up": _COLOURS[0], "down": _COLOURS[1]}
    for sweep in ("up", "down"):
        points = [r for r in rows if r["sweep"] == sweep]
        if not points:
            continue
        for stable in (True, False):
            xs, ys = [], []
            for run_x, run_y, run_stable in stability_runs(
                    [float(p["frequency"]) for p in points], [float(p["p2p"]) * unit for p in points],
                    [p["stable"] == "1" for p in points]):
                if run_stable == stable:
                    xs += run_x + [None]
                    ys += run_y + [None]
            if xs:
                extra = {"customdata": [None if x is None else x / per_rpm for x in xs],
                         "hovertemplate": "%{x:.4g} Hz (%{customdata:.4g} rpm)<br>%{y:.4g}"} if per_rpm else {}
                # The up sweep is drawn wide and pale under the down sweep: both stay visible
                # where the two coincide.
                style = {"color": colours[sweep], "dash": "solid" if stable else "dash",
                         "width": 5 if sweep == "up" else 1.8}
                data.append(line(xs, ys, f"sweep {sweep}, {'stable' if stable else 'unstable'}",
                                 legendgroup=sweep, line=style, opacity=0.45 if sweep == "up" else 1.0,
                                 **extra))
    return data


def hbm(folder, summary):
    results = summary["results"]
    si = summary["config"]["model"]["units"] == "SI"
    unit = 1e6 if si else 1.0
    rows = read_rows(folder / "sweep.csv")
    per_rpm = mesh_frequency_per_rpm(summary) if si else None
    data = forced_response_traces(rows, unit, per_rpm)
    folds = results.get("folds", [])
    if folds:
        data.append(markers([f["frequency"] for f in folds], [f["p2p"] * unit for f in folds], "folds",
                            "x", marker={"symbol": "x", "size": 9, "color": "black"}))
    checks = results.get("newmark_checks", [])
    if checks:
        data.append(markers([c["frequency"] for c in checks], [c["p2p_newmark"] * unit for c in checks],
                            "Newmark (time integration)", marker={"symbol": "circle-open", "size": 10, "color": "black"}))
    layout = axes_layout(f"{_title(summary, 'forced response')} (H = {results['harmonics']})",
                         "mesh frequency [Hz]" if si else "Ω = ω_m / ω_n [-]",
                         f"peak-to-peak y [{UM if si else '-'}]")
    out = [figure("Forced response", "Harmonic balance with continuation: solid stable, dashed unstable "
                  "(Hill's method), x folds, circles Newmark checks. Hover for values; drag to zoom.",
                  data, layout, 520)]
    details = results.get("details", [])
    if details:
        layout = rows_layout("one period at the detail frequencies", "τ = ω_m t [rad]",
                             [f"y [{UM if si else '-'}]", "contact force [N]", "F / y [N/m]"])
        data = []
        for i, detail in enumerate(details):
            table = _read_columns(folder / detail["file"], short=True)
            state = "stable" if detail["stable"] else "unstable"
            common = {"legendgroup": str(i), "line": {"color": _COLOURS[i % len(_COLOURS)]}}
            name = f"{detail['frequency']:g} Hz ({state})"
            data.append(line(table["tau"], [v * unit for v in table["y"]], name, **common))
            data.append(line(table["tau"], table["mesh_force"], name, row=1, showlegend=False, **common))
            data.append(line(table["tau"], table["mesh_stiffness"], name, row=2, showlegend=False, **common))
        out.append(figure("Periodic solutions", "One period of deflection, contact force and secant mesh "
                          "stiffness at the requested frequencies.", data, layout, 720))
    return out


def ltca(folder, summary):
    table = _read_columns(folder / "ltca.csv")
    layout = rows_layout(f"{_title(summary, 'loaded tooth contact')}: {summary['results']['ltca']['force']:g} N",
                         "mesh phase [periods]", [f"along the transverse line of action [{UM}]", "load share [-]"])
    data = [line(table["mesh_fraction"], [1e6 * v for v in table["ste_transverse_m"]], "loaded STE"),
            line(table["mesh_fraction"], [1e6 * v for v in table["no_load_te_transverse_m"]], "no-load TE", line={"dash": "dash"})]
    data += [line(table["mesh_fraction"], table[n], n.replace("share_", ""), row=1) for n in table if n.startswith("share_pair_")]
    out = [figure("Loaded tooth contact", "Loaded STE and load share of each tooth pair.", data, layout, 600)]
    if (folder / "harris.csv").exists():
        harris = _read_columns(folder / "harris.csv")
        data = [line(harris["force_transverse_n"], [1e6 * v for v in harris["peak_to_peak_m"]], "peak to peak", mode="lines+markers")]
        data += [line(harris["force_transverse_n"], [1e6 * v for v in harris[n]], n.replace("_m", "")) for n in harris
                 if n.startswith("harmonic_")]
        out.append(figure("Harris map", "Peak-to-peak loaded STE and its harmonics against load.", data,
                          axes_layout("Harris map", "transmitted force [N]", f"loaded STE [{UM}]")))
    return out


def identify(folder, summary):
    table = _read_columns(folder / "resimulated_peaks.csv")
    speeds = list(dict.fromkeys(table["speed_rpm"]))
    shafts = ("pinion", "gear")
    y_titles = [f"{shaft}, {speed:g} rpm [{UM}]" for speed in speeds for shaft in shafts]
    layout = rows_layout(_title(summary, "identification"), "frequency [Hz] (probe frame)", y_titles, share_x=True)
    data = []
    for k, (speed, shaft) in enumerate((s, sh) for s in speeds for sh in shafts):
        keep = [i for i in range(len(table["shaft"])) if table["shaft"][i] == shaft and table["speed_rpm"][i] == speed]
        f = [table["frequency_hz"][i] for i in keep]
        data.append({"type": "bar", "x": f, "y": [1e6 * table["measured_amplitude_m"][i] for i in keep],
                     "name": "measured", "legendgroup": "m", "showlegend": k == 0, "marker": {"color": "#999"},
                     "xaxis": f"x{k + 1}" if k else "x", "yaxis": f"y{k + 1}" if k else "y"})
        data.append(markers(f, [1e6 * table["model_amplitude_m"][i] for i in keep], "re-simulated", row=k,
                            legendgroup="r", showlegend=k == 0, marker={"color": _COLOURS[3], "size": 8,
                                                                        "symbol": "circle-open"}))
    return [figure("Measured and re-simulated whirl peaks", "Forward whirl at f > 0, backward at f < 0.",
                   data, layout, 260 * len(y_titles) + 80)]


def figures_of(folder, summary):
    """The report figures of a result folder, by the command that wrote it."""
    from . import _report_figures_rotor as rotor

    command = summary.get("command", "")
    builders = {"geometry": geometry, "stiffness": stiffness, "simulate": simulate, "stats": stats,
                "hbm": hbm, "ltca": ltca, "identify": identify, "spectrum": rotor.spectrum,
                "rotor": rotor.rotor, "sweep": rotor.sweep, "train": rotor.train}
    builder = builders.get(command)
    if command == "stats" and not (folder / "histogram.csv").exists():
        return []
    return builder(folder, summary) if builder else []
