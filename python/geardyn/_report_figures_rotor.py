"""Interactive report figures of rotors (lumped and finite-element), probe spectra, sweeps and
gear trains; see _report_figures for the figure format."""

import csv


from ._report_figures import (UM, _COLOURS, axes_layout, figure, line, log_range, markers,
                              rows_layout)
from ._tables import _long_table, _read_columns, keyphasor_points

_WHIRL_COLOURS = {"forward": "#d62728", "backward": "#1f77b4", "mixed": "#9467bd",
                  "torsional": "#2ca02c", "axial": "#8c564b"}


def _title(summary, fallback):
    return summary.get("config", {}).get("title") or fallback


def _orbits(folder, summary, only_steady):
    table = _read_columns(folder / "time_history.csv", short=True)
    keep = range(len(table["x1"]))
    if only_steady and "steady" in table:
        keep = [i for i in keep if table["steady"][i] == 1.0]
    layout = {"title": {"text": f"{_title(summary, 'orbits')}: orbits", "font": {"size": 14}},
              "hovermode": "closest", "margin": {"t": 60, "r": 20}}
    data = []
    frequencies = summary["results"].get("frequencies", {})
    t0 = summary["results"].get("keyphasor", {}).get("first_pulse_s", 0.0)
    for k, (shaft, xs, ys, f_name) in enumerate((("pinion shaft", "x1", "y1", "pinion_hz"),
                                                 ("gear shaft", "x2", "y2", "gear_hz"))):
        suffix = "" if k == 0 else "2"
        layout["xaxis" + suffix] = {"title": {"text": f"{shaft}: x [{UM}]"}, "domain": [0.55 * k, 0.55 * k + 0.45],
                                    "anchor": "y" + suffix}
        layout["yaxis" + suffix] = {"title": {"text": f"y [{UM}]"}, "anchor": "x" + suffix,
                                    "scaleanchor": "x" + suffix}
        orbit_x, orbit_y = [1e6 * table[xs][i] for i in keep], [1e6 * table[ys][i] for i in keep]
        data.append(line(orbit_x, orbit_y, shaft, xaxis="x" + suffix, yaxis="y" + suffix, line={"width": 1}))
        if frequencies.get(f_name):
            marks = keyphasor_points([table["t"][i] for i in keep], orbit_x, orbit_y, frequencies[f_name], t0)
            if marks:
                data.append(markers([m[0] for m in marks], [m[1] for m in marks], "keyphasor (once per rev)",
                                    xaxis="x" + suffix, yaxis="y" + suffix, legendgroup="kp", showlegend=k == 0,
                                    marker={"color": "black", "size": 6}))
    return figure("Orbits", "Whirl orbits of the two shafts (steady window); black dots: keyphasor, once "
                  "per revolution of that shaft.", data, layout, 500)


def _full_spectrum(folder, summary):
    spectrum = _read_columns(folder / "full_spectrum.csv")
    peaks = _read_columns(folder / "spectrum_peaks.csv")
    layout = rows_layout(f"{_title(summary, 'full spectrum')}: full spectra", "frequency [Hz] (forward > 0, backward < 0)",
                         [f"pinion 0-peak whirl radius [{UM}]", f"gear 0-peak whirl radius [{UM}]"])
    data = []
    for k, shaft in enumerate(("pinion", "gear")):
        f = [spectrum["frequency_hz"][i] for i, s in enumerate(spectrum["shaft"]) if s == shaft]
        a = [1e6 * spectrum["amplitude_m"][i] for i, s in enumerate(spectrum["shaft"]) if s == shaft]
        pf = [peaks["frequency_hz"][i] for i, s in enumerate(peaks["shaft"]) if s == shaft]
        pa = [1e6 * peaks["amplitude_m"][i] for i, s in enumerate(peaks["shaft"]) if s == shaft]
        data.append(line(f, a, "FFT", row=k, legendgroup="fft", showlegend=k == 0, line={"color": "#666", "width": 1}))
        data.append(markers(pf, pa, "whirl peaks", row=k, legendgroup="p", showlegend=k == 0,
                            marker={"color": _COLOURS[3], "symbol": "circle-open", "size": 7}))
        axis = layout["yaxis" + ("" if k == 0 else "2")]
        axis["type"] = "log"
        if log_range(a + pa):
            axis["range"] = log_range(a + pa)
    return figure("Full spectra", "Amplitude against signed frequency; the log axis shows six decades "
                  "below the largest peak.", data, layout, 640)


def _study(folder, summary):
    study = _read_columns(folder / "study.csv")
    cases = list(dict.fromkeys(study["case"]))
    components = [c for c in dict.fromkeys(study["component"]) if c != "static"]
    layout = rows_layout(f"{_title(summary, 'study')}: whirl amplitudes per case", "component",
                         [f"pinion shaft [{UM}]", f"gear shaft [{UM}]"])
    layout["barmode"] = "group"
    data, everything = [], []
    for k, shaft in enumerate(("pinion", "gear")):
        for j, case in enumerate(cases):
            values = {study["component"][i]: 1e6 * study["amplitude_m"][i] for i in range(len(study["case"]))
                      if study["case"][i] == case and study["shaft"][i] == shaft}
            ys = [values.get(c) for c in components]
            everything += [v for v in ys if v]
            data.append({"type": "bar", "x": components, "y": ys, "name": case, "legendgroup": case,
                         "showlegend": k == 0, "marker": {"color": _COLOURS[j % len(_COLOURS)]},
                         "xaxis": "x" if k == 0 else "x2", "yaxis": "y" if k == 0 else "y2"})
    for suffix in ("", "2"):
        layout["yaxis" + suffix]["type"] = "log"
        if log_range(everything):
            layout["yaxis" + suffix]["range"] = log_range(everything)
    return figure("Study", "Dynamic whirl amplitude of each component per case (log axis, six decades "
                  "below the largest).", data, layout, 640)


def spectrum(folder, summary):
    return [_orbits(folder, summary, False), _full_spectrum(folder, summary)]


def _fe_shaft_x(config, shaft):
    lengths = config.get(shaft, {}).get("element_lengths", [])
    xs = [0.0]
    for length in lengths:
        xs.append(xs[-1] + 1e3 * length)
    return xs


def _fe_modes(folder, summary):
    """Mode shapes along the shafts: |u_y| and |u_z| (real part, normalised) against x."""
    modes = _read_columns(folder / "modes.csv")
    shapes = _long_table(folder / "mode_shapes.csv", ["mode"])
    count = min(8, len(modes["mode"]))
    titles = [f"mode {int(modes['mode'][j])}: {modes['frequency_hz'][j]:.1f} Hz, {modes['whirl'][j]}"
              for j in range(count)]
    layout = rows_layout(f"{_title(summary, 'rotor')}: mode shapes along the shafts",
                         "x along the shaft [mm] (gear shaft drawn after the pinion shaft)",
                         titles, gap=0.03, share_x=True)
    data = []
    config = summary["config"]
    for j in range(count):
        shape = shapes[(str(int(modes["mode"][j])),)]
        values = dict(zip(shape["dof"], shape["re"]))
        largest = max([abs(v) for d, v in values.items() if d.endswith((".uy", ".uz", ".ux"))] + [1e-300])
        offset = 0.0
        for s, shaft in enumerate(("pinion_shaft", "gear_shaft")):
            xs = _fe_shaft_x(config, shaft)
            for dof, dash in (("uy", "solid"), ("uz", "dash")):
                ys = [values.get(f"{shaft}.{n}.{dof}", 0.0) / largest for n in range(len(xs))]
                data.append(line([offset + x for x in xs], ys, f"{shaft} u_{dof[1]}", row=j,
                                 legendgroup=shaft + dof, showlegend=j == 0, mode="lines+markers",
                                 line={"color": _COLOURS[s], "dash": dash}, marker={"size": 4}))
            offset += (xs[-1] if xs else 0.0) * 1.15
    for j in range(count):
        layout["yaxis" + ("" if j == 0 else str(j + 1))]["title"]["font"] = {"size": 9}
    return figure("Mode shapes", "Lateral displacement u_y (solid) and u_z (dashed) of each shaft node, "
                  "normalised per mode by its largest translation.", data, layout, 170 * count + 80)


def _fe_campbell(folder, summary):
    table = _long_table(folder / "campbell.csv", ["mode"])
    lines = _read_columns(folder / "campbell_lines.csv")
    critical = summary["results"]["campbell"]["critical_speeds"]
    data, top = [], 0.0
    for (mode,), d in sorted(table.items(), key=lambda kv: int(kv[0][0])):
        top = max(top, max(d["frequency_hz"]))
        colours = [_WHIRL_COLOURS.get(w, "#777") for w in d["whirl"]]
        data.append(line(d["speed_rpm"], d["frequency_hz"], f"mode {mode}", mode="lines+markers",
                         line={"color": "#999", "width": 1}, marker={"color": colours, "size": 5},
                         text=d["whirl"], hovertemplate="%{x:.0f} rpm, %{y:.1f} Hz, %{text}"))
    speeds = table[("1",)]["speed_rpm"]
    for name, order in zip(lines["line"], lines["order"]):
        data.append(line(speeds, [order * s / 60.0 for s in speeds], name, line={"dash": "dash"}))
    if critical:
        data.append(markers([c["speed_rpm"] for c in critical], [c["frequency_hz"] for c in critical],
                            "crossings (critical speeds)", marker={"symbol": "x", "size": 10, "color": "black"}))
    layout = axes_layout(f"{_title(summary, 'rotor')}: Campbell diagram", "pinion speed [rpm]", "frequency [Hz]")
    layout["yaxis"]["range"] = [0, 1.1 * top]
    return figure("Campbell diagram", "Modes against speed (marker colour: whirl, red forward, blue backward, "
                  "green torsional); dashed: order lines; x: crossings.", data, layout, 560)


def _fe_time(folder, summary):
    history = _read_columns(folder / "time_history.csv", short=True)
    channels = [c for c in history if c not in ("t", "speed_rpm", "mesh_stiffness", "mesh_force")
                and not c.endswith(("_vel", "_acc"))]
    layout = rows_layout(f"{_title(summary, 'rotor')}: time response", "time [s]",
                         [f"displacement [{UM}]", "mesh force [N]"])
    data = [line(history["t"], [1e6 * x for x in history[c]], c) for c in channels[:6]]
    data.append(line(history["t"], history["mesh_force"], "mesh force", row=1, line={"color": "black"}))
    out = [figure("Time history", "Response from rest; hover to read values.", data, layout, 600)]
    if (folder / "runup.csv").exists():
        track = _long_table(folder / "runup.csv", ["channel"])
        values = [v for d in track.values() for v in d["mesh_order_acceleration"]]
        data = [line(d["speed_rpm"], d["mesh_order_acceleration"], c) for (c,), d in track.items()]
        layout = axes_layout("order tracking of the run-up", "pinion speed [rpm]", "mesh-order acceleration [m/s²]",
                             y_log=True)
        if log_range(values):
            layout["yaxis"]["range"] = log_range(values)
        layout["shapes"] = [{"type": "line", "x0": c["speed_rpm"], "x1": c["speed_rpm"], "yref": "paper",
                             "y0": 0, "y1": 1, "line": {"dash": "dot", "color": "grey"}}
                            for c in summary["results"]["runup"]["campbell_mesh_crossings"]]
        out.append(figure("Run-up", "Mesh-order acceleration against speed; dotted: Campbell crossings of "
                          "the mesh line.", data, layout))
    return out


def _fe_compare(folder, summary):
    stiffness = _long_table(folder / "compare_stiffness.csv", ["model"])
    data = [line(d["mesh_fraction"], d["stiffness_normal_n_per_m"], m) for (m,), d in stiffness.items()]
    return [figure("Mesh-stiffness models", "The models compared over one mesh period.", data,
                   axes_layout(f"{_title(summary, 'rotor')}: mesh stiffness", "mesh phase [mesh periods]",
                               "k_m [N/m]"))]


def rotor(folder, summary):
    if summary["config"].get("model", {}).get("type") == "fe_geared_rotor":
        analysis = summary["config"]["analysis"]["type"]
        if analysis == "modal":
            return [_fe_modes(folder, summary)]
        if analysis == "campbell":
            return [_fe_campbell(folder, summary)]
        if analysis == "time":
            return _fe_time(folder, summary)
        if analysis == "compare_stiffness":
            return _fe_compare(folder, summary)
        return []
    out = []
    if (folder / "time_history.csv").exists():
        out.append(_orbits(folder, summary, True))
    if (folder / "full_spectrum.csv").exists():
        out.append(_full_spectrum(folder, summary))
    if (folder / "study.csv").exists():
        out.append(_study(folder, summary))
    return out


def sweep(folder, summary):
    study = summary["config"]["study"]
    with open(folder / "sweep.csv", newline="") as handle:
        rows = list(csv.DictReader(handle))
    outputs, parameters = list(study["outputs"]), list(study["parameters"])

    def number(text):
        try:
            return float(text)
        except ValueError:
            return float("nan")

    ok = [r for r in rows if r["status"] == "ok"]
    layout = rows_layout(study.get("title") or f"sweep of {study['command']}: {len(ok)} of {len(rows)} cases ok",
                         parameters[0], outputs, share_x=True)
    data = []
    colour_by = parameters[1] if len(parameters) > 1 else None
    for k, output in enumerate(outputs):
        data.append(markers([number(r[parameters[0]]) for r in ok], [number(r[output]) for r in ok], output, row=k,
                            text=[", ".join(f"{p} = {r[p]}" for p in parameters) for r in ok],
                            marker={"size": 7, "color": [number(r[colour_by]) for r in ok] if colour_by else _COLOURS[0],
                                    "colorscale": "Viridis", "showscale": bool(colour_by) and k == 0,
                                    "colorbar": {"title": {"text": colour_by or ""}}}))
    return [figure("Sweep", "Every case: each output against the first parameter"
                   + (f", coloured by {colour_by}" if colour_by else "") + "; hover for the case.",
                   data, layout, 260 * len(outputs) + 100)]


def _train_mode_shapes(folder, name, modes, count=16):
    """The mode shapes as a map: one column per mode, one row per degree of freedom, colour the
    real part normalised by the mode's largest entry (hover gives the value)."""
    shapes = _long_table(folder / "mode_shapes.csv", ["mode"])
    numbers = [int(m) for m in modes["mode"]][:count]
    dofs = list(shapes[(str(numbers[0]),)]["dof"])
    columns = []
    for m in numbers:
        values = dict(zip(shapes[(str(m),)]["dof"], shapes[(str(m),)]["real"]))
        largest = max(abs(v) for v in values.values()) or 1.0
        columns.append([values.get(d, 0.0) / largest for d in dofs])
    z = [[columns[j][i] for j in range(len(numbers))] for i in range(len(dofs))]
    labels = [f"{m}: {f:.0f} Hz" for m, f in zip(numbers, modes["frequency_hz"])]
    data = [{"type": "heatmap", "z": z, "x": labels, "y": dofs, "zmin": -1, "zmax": 1, "colorscale": "RdBu",
             "reversescale": True, "colorbar": {"title": {"text": "shape / largest [-]"}},
             "hovertemplate": "mode %{x}<br>%{y}: %{z:.3f}<extra></extra>"}]
    layout = axes_layout(f"{name}: mode shapes", "mode", "degree of freedom")
    layout["yaxis"]["autorange"] = "reversed"
    layout["margin"]["l"] = 160
    return figure("Mode shapes", "Every degree of freedom (rows) in each mode (columns): real part of the shape "
                  "normalised by its largest entry.", data, layout, min(1400, 140 + 14 * len(dofs)))


def train(folder, summary):
    results, out = summary["results"], []
    name = summary["config"].get("gearbox", {}).get("name") or "gear train"
    if "modal" in results and (folder / "modes.csv").exists():
        modes = _read_columns(folder / "modes.csv")
        data = [{"type": "bar", "x": [f"mode {int(m)}" for m in modes["mode"]], "y": modes["frequency_hz"],
                 "text": modes.get("stage_type"), "name": "natural frequency"}]
        out.append(figure("Modes", "Natural frequencies (hover: the kind of mode).", data,
                          axes_layout(f"{name}: modes", "mode", "natural frequency [Hz]")))
        if (folder / "mode_shapes.csv").exists():
            out.append(_train_mode_shapes(folder, name, modes))
    if "campbell" in results:
        table = _read_columns(folder / "campbell.csv")
        lines = _read_columns(folder / "order_lines.csv")
        speeds = table["speed_rpm"]
        top = 1.1 * max(max(v) for n, v in table.items() if n.startswith("mode_"))
        data = [line(speeds, v, n.replace("_", " "), line={"color": "#444", "width": 1})
                for n, v in table.items() if n.startswith("mode_")]
        data += [line(speeds, [slope * s for s in speeds], n, line={"dash": "dash" if n.startswith("1x ") else "dashdot"})
                 for n, slope in zip(lines["line"], lines["hz_per_rpm"])]
        if (folder / "critical_speeds.csv").stat().st_size:
            critical = _read_columns(folder / "critical_speeds.csv")
            if critical:
                data.append(markers(critical["speed_rpm"], critical["frequency_hz"], "crossings (critical speeds)",
                                    marker={"symbol": "x", "size": 9, "color": "black"}))
        layout = axes_layout(f"{name}: Campbell diagram", "input speed [rpm]", "natural frequency [Hz]")
        layout["yaxis"]["range"] = [0, top]
        out.append(figure("Campbell diagram", "Modes against speed with shaft (dashed) and mesh (dash-dot) "
                          "orders; x: crossings.", data, layout, 560))
    if "forced" in results:
        table = _read_columns(folder / "forced_response.csv")
        data = [line(table["speed_rpm"], v, n[len("dynamic_factor_"):]) for n, v in table.items()
                if n.startswith("dynamic_factor_")]
        out.append(figure("Forced response", "Dynamic factor of each mesh against input speed.", data,
                          axes_layout(f"{name}: forced response", "input speed [rpm]", "dynamic factor max F / mean F [-]")))
    if "time" in results and (folder / "time_history.csv").exists():
        table = _read_columns(folder / "time_history.csv")
        t_ms = [1e3 * (t - table["t_s"][0]) for t in table["t_s"]]
        data = [line(t_ms, [1e-3 * f for f in v], n[len("mesh_force_"):-len("_normal_n")])
                for n, v in table.items() if n.startswith("mesh_force_") and n.endswith("_normal_n")]
        out.append(figure("Time history", "Dynamic mesh forces in the steady window.", data,
                          axes_layout(f"{name}: mesh forces", "time [ms]", "mesh force [kN]")))
    if "stats" in results and (folder / "mesh_statistics.csv").exists():
        out.append(_train_mesh_statistics(folder, name))
    return out


def _train_mesh_statistics(folder, name):
    """Gelman's R (curves and Newmark record) and the dynamic factor of every mesh, as bars."""
    table = _read_columns(folder / "mesh_statistics.csv")
    meshes = [str(m) for m in table["mesh"]]

    def numbers(column):
        out = []
        for v in table[column]:
            try:
                out.append(float(v))
            except (TypeError, ValueError):
                out.append(None)
        return out

    data = [{"type": "bar", "x": meshes, "y": numbers("mean_excitation_ratio"),
             "name": "R (Gelman eqs. 5–7)"},
            {"type": "bar", "x": meshes, "y": numbers("simulated_mean_excitation_ratio"),
             "name": "R from the Newmark record"},
            {"type": "bar", "x": meshes, "y": numbers("dynamic_factor"),
             "name": "dynamic factor max |F| / F"}]
    layout = axes_layout(f"{name}: mesh statistics", "mesh", "ratio [-]", barmode="group")
    return figure("Mesh statistics", "Gelman's mean excitation ratio R of every mesh, from the "
                  "curves and from the Newmark record, and the dynamic factor.", data, layout)


