"""The report of a consistent-remesh run: report.json, the run's figures,
and report.md and report.html, what it did, for people.

The last two are made from one list of blocks (headings, paragraphs, tables,
pictures) built from the run's report.json content, so they say the same.
The pictures are the PNGs beside them, linked by file name, so the folder
can be moved or shared as a whole.

How long things took, and when the run was, go to timings.json alone:
report.json, report.md and report.html are then the same byte for byte
from run to run of one command on the same inputs, and can be diffed.
"""

import html
import json
import os
import shlex
from urllib.parse import quote

TIMINGS_FILE = "timings.json"
FILES = ("report.json", "report.md", "report.html", TIMINGS_FILE)


class Heading:
    def __init__(self, text):
        self.text = text


class Paragraph:
    def __init__(self, text):
        self.text = text


class Table:
    def __init__(self, header, rows):
        self.header = header
        self.rows = rows


class Picture:
    def __init__(self, file, caption):
        self.file = file
        self.caption = caption


def is_timing(key):
    """Whether a report key holds a time: "seconds", "..._seconds"."""
    return key == "seconds" or key.endswith("_seconds")


def split_timings(report):
    """(the report without its timings, the timings): every "seconds" or
    "..._seconds" entry, at any depth, moves to the second, under the same
    keys as it had in the first."""
    results, timings = {}, {}
    for key, value in report.items():
        if is_timing(key):
            timings[key] = value
        elif isinstance(value, dict):
            results[key], inner = split_timings(value)
            if inner:
                timings[key] = inner
        else:
            results[key] = value
    return results, timings


def write(report, output_folder, run=None):
    """Writes report.json, report.md and report.html into `output_folder`,
    from `report` without its timings, and timings.json with them and
    `run` (when the run started, how long it took) under "run"."""
    report, timings = split_timings(report)
    if run is not None:
        timings = dict({"run": run}, **timings)
    with open(os.path.join(output_folder, FILES[0]), "w") as out:
        json.dump(report, out, indent=2)
        out.write("\n")
    with open(os.path.join(output_folder, TIMINGS_FILE), "w") as out:
        json.dump(timings, out, indent=2)
        out.write("\n")
    blocks = build(report)
    with open(os.path.join(output_folder, FILES[1]), "w") as out:
        out.write(markdown(blocks))
    with open(os.path.join(output_folder, FILES[2]), "w") as out:
        out.write(html_page(blocks, _title(report)))


def _title(report):
    data = report.get("collection")
    return "Consistent remeshing" + (": %s" % data["title"] if data else "")


def build(report):
    """The report's blocks, in reading order."""
    blocks = [Heading(_title(report))]
    data = report.get("collection")
    if data:
        blocks.append(Paragraph("%s. The meshes were unpacked to %s." % (data["description"], data["meshes"])))
    blocks.append(Paragraph("Command: `%s`. How long each stage took, and when the run was, is in %s (every "
                            "other file of the run is the same for the same command and inputs)."
                            % (shlex.join(report.get("command", [])), TIMINGS_FILE)))
    blocks += _summary(report)
    blocks += _models(report)
    pictures = report.get("renders", {})
    drawn = set(pictures.get("files", []))
    if "skipped" in pictures:
        blocks.append(Paragraph("No pictures: %s." % pictures["skipped"]))
    blocks += _section("Patch layouts", drawn, "inputs.png",
                       "Each model's surface cut into the patches of the base domain's triangles, with the "
                       "straightened net drawn over it. A patch has the same colour on every model.")
    blocks += _section("Remeshes", drawn, "remeshes.png",
                       "The semi-regular remeshes: vertex k of one is vertex k of every other. Colours are the base "
                       "triangles, as above.")
    blocks += _pca(report, drawn)
    blocks += _blends(report, drawn)
    blocks += _transfer(report, drawn)
    blocks += _details(report)
    for note in pictures.get("notes", []):
        blocks.append(Paragraph("Note: %s." % note))
    for name, error in pictures.get("errors", {}).items():
        blocks.append(Paragraph("%s could not be drawn: %s." % (name, error)))
    return blocks


def _summary(report):
    models = report["models"]
    ok = [name for name, model in models.items() if model.get("status") == "ok"]
    lines = []
    remesh = report.get("remesh", {})
    if "vertices" in remesh:
        adaptive = ""
        if remesh["adaptive_tolerance"]:
            passes = remesh.get("adaptive_passes", 1)
            adaptive = ", adaptive (tolerance %g, made in %d pass%s)" % (remesh["adaptive_tolerance"], passes,
                                                                        "" if passes == 1 else "es")
        rounds = remesh.get("sample_relaxation_rounds", 0)
        if rounds:
            adaptive += ", samples relaxed (%d round%s)" % (rounds, "" if rounds == 1 else "s")
        lines.append("%d of %d models remeshed with one connectivity: level %d%s, %d vertices and %d triangles "
                     "each." % (len(ok), len(models), remesh["level"], adaptive, remesh["vertices"],
                                remesh["triangles"]))
    elif "error" in remesh:
        lines.append("Remeshing the collection failed: %s." % remesh["error"])
    domain = report.get("base_domain", {})
    if "error" in domain:
        lines.append("No base domain: %s." % domain["error"])
    else:
        angle = ", smallest angle %.2f°" % domain["min_angle_degrees"] if "min_angle_degrees" in domain else ""
        lines.append("Base domain: %d vertices, %d triangles, %d edges%s (%s)."
                     % (domain["vertices"], domain["triangles"], domain["edges"], angle, domain["source"]))
    placed = ["%s: %s" % (name, ", ".join("feature %d at vertex %d" % (entry["feature"], entry["vertex"])
                                          for entry in model["placed_landmarks"]))
              for name, model in report["models"].items() if model.get("placed_landmarks")]
    if placed:
        lines.append("Landmarks missing in the files, placed from the models that have them (before the "
                     "base domain was used): %s." % "; ".join(placed))
    if "error" in report.get("placement", {}):
        lines.append("The missing landmarks could not be placed: %s." % report["placement"]["error"])
    if report.get("failed"):
        lines.append("**Failed:** %s." % ", ".join(report["failed"]))
    return [Heading("Summary")] + [Paragraph(line) for line in lines]


def _models(report):
    header = ["model", "vertices", "triangles", "net / √area, traced", "straightened", "flipped parameter triangles",
              "Hausdorff / diagonal", "farthest point: nearest landmark (distance / diagonal)",
              "flipped remesh triangles (nearest landmark: how many)", "flipped by the centroid criterion", "result"]
    rows = []
    for name, model in report["models"].items():
        remesh = model.get("remesh", {})
        hausdorff = remesh.get("hausdorff_per_diagonal")
        rows.append([
            name, model.get("vertices", "-"), model.get("triangles", "-"),
            model.get("net", {}).get("length_per_sqrt_area", "-"),
            model.get("straighten", {}).get("net_length_per_sqrt_area_after", "-"),
            model.get("straighten", {}).get("flipped_triangles", "-"),
            "-" if hausdorff is None else "%.2f %%" % (100 * hausdorff),
            _farthest(remesh),
            _folds(remesh),
            remesh.get("centroid_flips", "-"),
            "ok" if model.get("status") == "ok" else "failed: %s" % model.get("error", ""),
        ])
    return [Heading("Models"), Table(header, rows)]


def _folds(remesh):
    """The remesh's folded triangles and the landmarks they lie nearest to."""
    near = remesh.get("folds_near_landmark")
    if not near:
        return remesh.get("flipped_triangles", "-")
    return "%d (near %s)" % (remesh["flipped_triangles"], ", ".join("%s: %d" % item for item in near.items()))


def _farthest(remesh):
    """Where the Hausdorff distance is reached, as the landmark nearest to
    it: on the input, a part the remesh misses lies past that landmark."""
    if "hausdorff_nearest_landmark" not in remesh:
        return "-"
    return "%d (%.3f) on the %s" % (remesh["hausdorff_nearest_landmark"],
                                    remesh["hausdorff_landmark_distance_per_diagonal"], remesh["hausdorff_point_on"])


def _section(title, drawn, file, text):
    if file not in drawn:
        return []
    return [Heading(title), Paragraph(text), Picture(file, title)]


def _pca(report, drawn):
    pca = report.get("pca")
    if pca is None:
        return []
    blocks = [Heading("Mean and modes of variation")]
    if "error" in pca:
        return blocks + [Paragraph("Failed: %s." % pca["error"])]
    blocks.append(Paragraph("The mean of the %d models after %s alignment (%d iterations), and %d modes that "
                            "explain %.1f %% of the variance."
                            % (len(pca["models"]), pca["alignment"], pca["alignment_iterations"], pca["modes"],
                               100 * pca["explained_variance"])))
    rows = [["Mode%d" % k, "%.6g" % v, "%.6g" % d, "%.1f %%" % (100 * r)]
            for k, (v, d, r) in enumerate(zip(pca["variances"], pca["standard_deviations"],
                                              pca["explained_variance_ratios"]))]
    blocks.append(Table(["mode", "variance", "standard deviation", "explained"], rows))
    for file, caption in (("mean.png", "The mean shape"),
                          ("pca-modes.png", "The mean moved by -2, 0 and +2 standard deviations along each mode")):
        if file in drawn:
            blocks.append(Picture(file, caption))
    return blocks


def _blends(report, drawn):
    blocks = []
    grid = report.get("blend_grid")
    if grid is not None:
        blocks.append(Heading("Blends"))
        if "error" in grid:
            blocks.append(Paragraph("Failed: %s." % grid["error"]))
        else:
            blocks.append(Paragraph("%d blends of %s (%s alignment): the corners are the models, every other "
                                    "shape a weighted average of their remeshes, vertex by vertex."
                                    % (grid["blends"], ", ".join(grid["models"]), grid["alignment"])))
            if "blend-grid.png" in drawn:
                blocks.append(Picture("blend-grid.png", "Blends"))
    blend = report.get("blend")
    if blend is not None:
        weights = ", ".join("%s %g" % item for item in blend["weights"].items())
        blocks.append(Heading("Blend with weights %s" % weights))
        if "error" in blend:
            blocks.append(Paragraph("Failed: %s." % blend["error"]))
        elif "blend.png" in drawn:
            blocks.append(Picture("blend.png", "Blend"))
    return blocks


def _transfer(report, drawn):
    transfer = report.get("transfer")
    if transfer is None:
        return []
    blocks = [Heading("Texture transfer from %s" % transfer["source"])]
    if "error" in transfer:
        return blocks + [Paragraph("Failed: %s." % transfer["error"])]
    text = "%s's texture coordinates and point arrays carried onto every other remesh" % transfer["source"]
    if "texture_coordinates" in transfer:
        text += " (texture coordinates %s; in the pictures a square of the checkerboard covers the same part of " \
                "every model)" % transfer["texture_coordinates"]
    blocks.append(Paragraph(text + "."))
    for target in transfer["targets"]:
        file = "%s.from-%s.png" % (target, transfer["source"])
        if file in drawn:
            blocks.append(Picture(file, "%s's texture on %s" % (transfer["source"], target)))
    return blocks


def _details(report):
    details = report.get("details")
    if details is None:
        return []
    blocks = [Heading("Detail transfer from %s" % details["source"])]
    if "error" in details:
        return blocks + [Paragraph("Failed: %s." % details["error"])]
    files = ", ".join(target["file"] for target in details["targets"].values())
    return blocks + [Paragraph("Every other model's levels 0 to %d with %s's finer wavelet details: %s."
                               % (details["last_coarse_level"], details["source"], files))]


def markdown(blocks):
    lines = []
    for block in blocks:
        if isinstance(block, Heading):
            lines.append(("# " if not lines else "## ") + block.text)
        elif isinstance(block, Paragraph):
            lines.append(block.text)
        elif isinstance(block, Table):
            lines.append("| " + " | ".join(block.header) + " |")
            lines.append("|" + "---|" * len(block.header))
            lines += ["| " + " | ".join(str(cell).replace("|", "\\|") for cell in row) + " |" for row in block.rows]
        elif isinstance(block, Picture):
            # Encoded: a model's name may hold spaces or # (a file name).
            lines.append("![%s](%s)" % (block.caption, quote(block.file)))
        lines.append("")
    return "\n".join(lines)


def html_page(blocks, title):
    body = []
    for index, block in enumerate(blocks):
        if isinstance(block, Heading):
            tag = "h1" if index == 0 else "h2"
            body.append("<%s>%s</%s>" % (tag, html.escape(block.text), tag))
        elif isinstance(block, Paragraph):
            body.append("<p>%s</p>" % _inline_html(block.text))
        elif isinstance(block, Table):
            head = "".join("<th>%s</th>" % html.escape(str(cell)) for cell in block.header)
            rows = "".join("<tr>%s</tr>" % "".join("<td>%s</td>" % html.escape(str(cell)) for cell in row)
                           for row in block.rows)
            body.append("<table><tr>%s</tr>%s</table>" % (head, rows))
        elif isinstance(block, Picture):
            body.append('<figure><img src="%s" alt="%s"><figcaption>%s</figcaption></figure>'
                        % (html.escape(quote(block.file)), html.escape(block.caption), html.escape(block.caption)))
    style = ("body{font-family:sans-serif;max-width:1250px;margin:2em auto;color:#222}"
             "table{border-collapse:collapse}td,th{border:1px solid #ccc;padding:3px 8px;text-align:right}"
             "td:first-child,th{text-align:left}img{max-width:100%}figcaption{color:#555}")
    return ("<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>%s</title><style>%s</style></head>\n"
            "<body>\n%s\n</body></html>\n" % (html.escape(title), style, "\n".join(body)))


def _inline_html(text):
    """Markdown's `code` and **bold** of a paragraph, in HTML."""
    parts = html.escape(text).split("`")
    text = "".join("<code>%s</code>" % part if index % 2 else part for index, part in enumerate(parts))
    parts = text.split("**")
    return "".join("<b>%s</b>" % part if index % 2 else part for index, part in enumerate(parts))
