"""The parts of an mrt_sim world YAML (format: mrt_sim/README.md) that
plot_run draws under the trajectories: walls, field lines (segments and arcs),
posts, goals and the movers' waypoints. Metres; arc limits in degrees."""
import math

import yaml


class WorldError(Exception):
    """A world file that cannot be drawn; the message names the file."""


class World:
    def __init__(self):
        self.name = ""
        self.bounds = None          # [xmin, ymin, xmax, ymax] or None
        self.walls = []             # [(x1, y1, x2, y2)]
        self.lines = []             # [(x1, y1, x2, y2)] painted lines, arcs expanded
        self.posts = []             # [(x, y, radius, colour, name)]
        self.goals = []             # [(x, y, colour, name)]
        self.movers = []            # [([x], [y], colour, name)]


def _segment(path, key, i, item):
    if not isinstance(item, (list, tuple)) or len(item) != 4:
        raise WorldError(f"{path}: {key}[{i}]: expected [x1, y1, x2, y2]")
    return tuple(float(v) for v in item)


def _arc(path, i, item):
    """An arc {center, radius, segments, from, to} as its chords."""
    try:
        cx, cy = (float(v) for v in item["center"])
        r = float(item["radius"])
        n = int(item.get("segments", 24))
        a0 = math.radians(float(item.get("from", 0.0)))
        a1 = math.radians(float(item.get("to", 360.0)))
    except (KeyError, TypeError, ValueError) as e:
        raise WorldError(f"{path}: field_lines[{i}]: expected an arc "
                         f"{{center: [x, y], radius: r, segments: n, from: deg, to: deg}} ({e})")
    if n < 1:
        raise WorldError(f"{path}: field_lines[{i}]: expected segments >= 1")
    pts = [(cx + r * math.cos(a0 + (a1 - a0) * k / n), cy + r * math.sin(a0 + (a1 - a0) * k / n))
           for k in range(n + 1)]
    return [(p[0], p[1], q[0], q[1]) for p, q in zip(pts, pts[1:])]


def load_world(path):
    """Reads the world file at path; raises WorldError naming the file."""
    try:
        with open(path) as f:
            doc = yaml.safe_load(f)
    except OSError as e:
        raise WorldError(f"{path}: cannot read ({e.strerror})")
    except yaml.YAMLError as e:
        mark = getattr(e, "problem_mark", None)
        where = f":{mark.line + 1}:{mark.column + 1}" if mark else ""
        raise WorldError(f"{path}{where}: not valid YAML ({getattr(e, 'problem', e)})")
    if not isinstance(doc, dict):
        raise WorldError(f"{path}: expected a mapping with walls, field_lines, posts ...")
    w = World()
    w.name = str(doc.get("name", ""))
    if isinstance(doc.get("bounds"), list) and len(doc["bounds"]) == 4:
        w.bounds = [float(v) for v in doc["bounds"]]
    w.walls = [_segment(path, "walls", i, s) for i, s in enumerate(doc.get("walls") or [])]
    for i, item in enumerate(doc.get("field_lines") or []):
        if isinstance(item, dict):
            w.lines.extend(_arc(path, i, item))
        else:
            w.lines.append(_segment(path, "field_lines", i, item))
    try:
        for p in doc.get("posts") or []:
            w.posts.append((float(p["x"]), float(p["y"]), float(p.get("radius", 0.1)),
                            str(p.get("color", "grey")), str(p.get("name", ""))))
        for g in doc.get("goals") or []:
            w.goals.append((float(g["x"]), float(g["y"]), str(g.get("color", "grey")), str(g.get("name", ""))))
        for m in doc.get("movers") or []:
            pts = m.get("waypoints") or []
            w.movers.append(([float(p[0]) for p in pts], [float(p[1]) for p in pts],
                             str(m.get("color", "grey")), str(m.get("name", ""))))
    except (KeyError, TypeError, ValueError, IndexError) as e:
        raise WorldError(f"{path}: expected posts/goals with x, y and movers with waypoints ({e})")
    return w
