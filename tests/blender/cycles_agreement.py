"""The real-renderer test (docs/HOSTS.md, Blender): Cycles in Blender 3.4 renders brdfnav's
materials as hosts/blender/brdfnav_cycles.py builds them, and brdfnav's metric compares the
images with brdfnav's own renders of the same materials. Runs inside Blender:

    blender -b --factory-startup --python-exit-code 1 --python tests/blender/cycles_agreement.py \\
        -- --cli build/bin/brdfnav --db DB --out DIR [--res 128] [--samples 1024]

- ggx materials, near-mirror to rough, coloured: Cycles' image against brdfnav's, at most
  0.25 eps (eps = 0.03) in the cube-root metric;
- a Ward, a Lafortune and a He material, exported for Cycles (`brdfnav export --format cycles`,
  their ggx equivalent from the database DB, residual rendered at --res): Cycles' image of the
  export against brdfnav's of the original within 20% of the residual the export states;
- first, the script's other entry points: it reads a material file and a YAML export as it reads
  the JSON one, builds the node tree on an artist's object (roughness and anisotropy give back
  the alphas as Cycles 3.4 computes them) and registers its operator.

Every image, the exports and results.txt (the table printed) stay in DIR. Exit status 1 when a
comparison fails.
"""

import argparse
import os
import subprocess
import sys
import time

EPS = 0.03
GGX_TOLERANCE = 0.25 * EPS
RESIDUAL_TOLERANCE = 0.2

# (name, inline spec): near-mirror to rough, grey and coloured, isotropic and anisotropic.
GGX_MATERIALS = [
    ("ggx_mirror_silver", "ggx:alpha_x=0.01,alpha_y=0.01,rho_d=0,rho_s=0.95/0.93/0.88"),
    ("ggx_smooth_gold", "ggx:alpha_x=0.03,alpha_y=0.03,rho_d=0,rho_s=1/0.71/0.29"),
    ("ggx_brushed_blue", "ggx:alpha_x=0.02,alpha_y=0.15,rho_d=0.05/0.1/0.3,rho_s=0.9/0.6/0.3"),
    ("ggx_medium_grey", "ggx:alpha_x=0.1,alpha_y=0.1,rho_d=0.1,rho_s=0.8"),
    ("ggx_brushed_green", "ggx:alpha_x=0.4,alpha_y=0.08,rho_d=0.02,rho_s=0.3/0.8/0.5"),
    ("ggx_rough_clay", "ggx:alpha_x=1,alpha_y=1,rho_d=0.2/0.1/0.05,rho_s=0.5"),
]
# Materials of other models, exported for Cycles through their ggx equivalent.
OTHER_MATERIALS = [
    ("ward", "ward:alpha_x=0.05,alpha_y=0.2,rho_d=0.1/0.15/0.2,rho_s=0.5"),
    ("lafortune", "lafortune:cz=0.56,n=300,rho_d=0.15/0.1/0.05,rho_s=0.6"),
    ("he", "he:sigma=0.3,tau=8,eta=1.5,rho_d=0.05/0.1/0.2,rho_s=1"),
]


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--cli", required=True, help="the brdfnav executable")
    parser.add_argument("--db", required=True, help="a database with the ggx model")
    parser.add_argument("--out", required=True, help="directory for the images and results")
    parser.add_argument("--res", type=int, default=128)
    parser.add_argument("--samples", type=int, default=1024,
                        help="Cycles' samples per pixel for the ggx materials")
    parser.add_argument("--equivalent-samples", type=int, default=128,
                        help="... for the other models' exports, whose residuals are large "
                             "against the noise")
    args = parser.parse_args(argv)
    import bpy
    if tuple(bpy.app.version[:2]) != (3, 4):
        print(f"cycles_agreement: Blender {bpy.app.version_string}: the ggx closure is Cycles 3.4's "
              "GGX, which later versions changed", file=sys.stderr)
        return 1
    os.makedirs(args.out, exist_ok=True)
    here = os.path.dirname(os.path.abspath(__file__))
    sys.path.insert(0, os.path.join(here, "..", "..", "hosts", "blender"))
    import brdfnav_cycles

    def path(name):
        return os.path.join(args.out, name)

    def cli(*words):
        done = subprocess.run([args.cli, *words], capture_output=True, text=True)
        if done.returncode != 0:
            raise RuntimeError(f"brdfnav {' '.join(words)}: exit {done.returncode}\n{done.stderr}")
        return done.stdout

    # The database's map: what brdfnav renders under by default, and what the exports state.
    env = _manifest_env(os.path.join(args.db, "manifest.yaml"))
    check_entry_points(brdfnav_cycles, cli, args.db, path)
    started = time.monotonic()
    cases = []  # (name, exported file, brdfnav image, stated residual or None)
    for name, spec in GGX_MATERIALS + OTHER_MATERIALS:
        export = path(f"{name}.json")
        cli("export", "--db", args.db, "--material", spec, "--format", "cycles", "--res",
            str(args.res), "--out", export)
        cli("render", "--material", spec, "--env", env, "--res", str(args.res), "--out",
            path(f"{name}.brdfnav.exr"))
        stated = None if spec.startswith("ggx:") else brdfnav_cycles.load(export)["residual"]
        cases.append((name, export, path(f"{name}.brdfnav.exr"), stated))
    brdfnav_seconds = time.monotonic() - started

    started = time.monotonic()
    sphere = brdfnav_cycles.sphere_scene(env, args.res, args.samples)
    for name, export, _, stated in cases:
        brdfnav_cycles.render_sphere(sphere, brdfnav_cycles.load(export), path(f"{name}.cycles.exr"),
                                     args.samples if stated is None else args.equivalent_samples)
    cycles_seconds = time.monotonic() - started

    lines = [f"Cycles (Blender 3.4) against brdfnav at {args.res} x {args.res} under {env}: "
             f"{args.samples} samples per pixel for the ggx materials, "
             f"{args.equivalent_samples} for the exports of the others",
             f"brdfnav exports and renders: {brdfnav_seconds:.0f} s; Cycles: {cycles_seconds:.0f} s "
             f"for {len(cases)} images",
             "",
             "| material | distance | in eps | criterion | |",
             "|---|---|---|---|---|"]
    failed = False
    for name, _, reference, stated in cases:
        d = float(cli("distance", path(f"{name}.cycles.exr"), reference))
        if stated is None:
            ok = d <= GGX_TOLERANCE
            criterion = f"<= {GGX_TOLERANCE:g} (0.25 eps)"
        else:
            ok = abs(d - stated) <= RESIDUAL_TOLERANCE * stated
            criterion = (f"stated residual {stated:.4g}: within 20% "
                         f"({(d - stated) / stated:+.1%})")
        failed |= not ok
        lines.append(f"| {name} | {d:.4f} | {d / EPS:.3f} | {criterion} | "
                     f"{'ok' if ok else 'FAILED'} |")
    text = "\n".join(lines) + "\n"
    print(text)
    with open(path("results.txt"), "w", encoding="utf-8") as f:
        f.write(text)
    return 1 if failed else 0


def check_entry_points(brdfnav_cycles, cli, db, path):
    """The script as an artist's scene and a pipeline use it; raises AssertionError."""
    import bpy
    spec = "ggx:alpha_x=0.3,alpha_y=0.05,rho_d=0.1/0.2/0.3,rho_s=0.7"
    material_file = path("entry.yaml")
    with open(material_file, "w", encoding="utf-8") as f:
        f.write("brdfnav_material: 1\nmodel: ggx\nparams: {alpha_x: 0.3, alpha_y: 0.05}\n"
                "rho_d: [0.1, 0.2, 0.3]\nrho_s: [0.7, 0.7, 0.7]\ncolorspace: lin_rec709\n")
    cli("export", "--db", db, "--material", spec, "--format", "cycles", "--out", path("entry.json"))
    from_file, from_json = brdfnav_cycles.load(material_file), brdfnav_cycles.load(path("entry.json"))
    assert from_file == from_json, (from_file, from_json)
    ward = "ward:alpha_x=0.05,alpha_y=0.2,rho_d=0.1,rho_s=0.5"
    cli("export", "--db", db, "--material", ward, "--out", path("entry_ward.yaml"))
    cli("export", "--db", db, "--material", ward, "--format", "cycles", "--res", "16", "--out",
        path("entry_ward.json"))
    yaml_export, json_export = (brdfnav_cycles.load(path("entry_ward.yaml")),
                                brdfnav_cycles.load(path("entry_ward.json")))
    for key in ("alpha_x", "alpha_y", "rho_d", "rho_s"):
        assert yaml_export[key] == json_export[key], (key, yaml_export, json_export)

    bpy.ops.wm.read_factory_settings(use_empty=True)
    bpy.ops.mesh.primitive_cube_add()
    cube = bpy.context.object
    material = brdfnav_cycles.apply(cube, from_json)
    nodes = {n.bl_idname: n for n in material.node_tree.nodes}
    glossy = nodes["ShaderNodeBsdfAnisotropic"]
    assert glossy.distribution == "GGX"
    r, a = glossy.inputs["Roughness"].default_value, glossy.inputs["Anisotropy"].default_value
    # Cycles 3.4 (svm_closure.h): alpha_x = r^2 / (1 + a), alpha_y = r^2 (1 + a) for a < 0.
    assert a < 0 and abs(r * r / (1 + a) - 0.3) < 1e-6 and abs(r * r * (1 + a) - 0.05) < 1e-6, \
        (r, a)
    diffuse = tuple(nodes["ShaderNodeBsdfDiffuse"].inputs["Color"].default_value)[:3]
    assert all(abs(c - e) < 1e-6 for c, e in zip(diffuse, (0.1, 0.2, 0.3))), diffuse
    assert nodes["ShaderNodeBsdfDiffuse"].inputs["Roughness"].default_value == 0
    brdfnav_cycles.register()
    assert hasattr(bpy.ops.object, "brdfnav_load_material")
    brdfnav_cycles.unregister()


def _manifest_env(manifest):
    """The environment map's path in a database manifest (environment: path: ...)."""
    with open(manifest, encoding="utf-8") as f:
        lines = f.read().splitlines()
    for i, line in enumerate(lines):
        if line.startswith("environment:"):
            for sub in lines[i + 1:]:
                key, _, value = sub.strip().partition(":")
                if key == "path":
                    return value.strip().strip('"')
    raise RuntimeError(f"{manifest}: no environment path")


if __name__ == "__main__":
    sys.exit(main(sys.argv[sys.argv.index("--") + 1:] if "--" in sys.argv else []))
