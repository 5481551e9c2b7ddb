#!/usr/bin/python3
"""The house rules of src/, checked on the sources.

1. Modules form a one-way stack: a file of src/M includes headers of M and of the modules listed
   before M in CAMBRIAN_MODULES (src/CMakeLists.txt) only, public headers (include/cambrian/)
   counted as the module that owns them (OWNER below; every public header must be listed).
2. Public headers include public headers and the standard library only.
3. MPI, HDF5, Bullet and Boost each stay behind their one module (their headers' only includers).
4. Programs outside src/ (bench/) may include any module's headers, as the tests do, but the
   third-party headers stay confined there too (CONFINED names the one exception).

usage: module_order_check.py SOURCE_DIR        exit 1 listing every broken rule
"""

import pathlib
import re
import sys

# the module that owns each public header (a new header must be added here)
OWNER = {
    "error.hpp": "core",
    "math.hpp": "core",
    "rng.hpp": "core",
    "outcome.hpp": "core",
    "version.hpp": "core",
    "body_plan.hpp": "body",
    "controller.hpp": "brain",
    "encoding.hpp": "genome",
    "encodings.hpp": "encodings",
    "environment.hpp": "physics",
    "evaluate.hpp": "tasks",
}

# third-party headers and the only places allowed to include them (path prefixes under the
# source root): Bullet in the two physics worlds and what they share (bullet_scene, included by
# them only), and the rigid-body world's solver with ODE's soft rows (soft_constraints). bench/step_cost.cpp measures cambrian against a bare Bullet loop it writes by hand:
# that loop must use Bullet directly, and the program is no part of any cambrian library. Boost's
# odeint integrates the chaotic controllers' circuits; Boost.Container's small_vector keeps a
# directed-graph gene's short lists inside it; the rest of Boost parses the command line.
CONFINED = [
    (re.compile(r"^mpi\.h$"), ["src/parallel/mpi_context.cpp"]),
    (re.compile(r"^hdf5\.h$|^H5"), ["src/store/"]),
    (re.compile(r"^(btBulletDynamicsCommon|BulletDynamics|BulletCollision|LinearMath)"),
     ["src/physics/featherstone_world.cpp", "src/physics/rigid_body_world.cpp",
      "src/physics/bullet_scene.", "src/physics/soft_constraints.", "src/physics/world.cpp",
      "bench/step_cost.cpp"]),
    (re.compile(r"^boost/numeric/odeint"), ["src/brain/chua_oscillators.cpp"]),
    (re.compile(r"^boost/container/small_vector"), ["src/encodings/directed_graph/genome.hpp"]),
    (re.compile(r"^boost/(?!numeric/odeint|container/small_vector)"), ["src/app/"]),
]

# folders of programs outside src/ that link cambrian's libraries (rule 4)
OUTSIDE_SRC = ["bench"]

INCLUDE = re.compile(r'^\s*#\s*include\s*([<"])([^>"]+)[>"]', re.M)


def modules(source):
    text = (source / "src" / "CMakeLists.txt").read_text()
    match = re.search(r"set\(CAMBRIAN_MODULES([^)]*?)CACHE", text, re.S)
    if not match:
        sys.exit("module_order_check: no set(CAMBRIAN_MODULES ...) in src/CMakeLists.txt")
    return match.group(1).split()


def confined_problems(relative, text):
    """Rule 3: the third-party headers that the file `relative` (to the source root), of text
    `text`, includes outside the places CONFINED allows."""
    problems = []
    for _, name in INCLUDE.findall(text):
        for pattern, allowed in CONFINED:
            if pattern.search(name) and not any(relative.startswith(a) for a in allowed):
                problems.append(f"{relative}: includes <{name}>, which only "
                                f"{', '.join(allowed)} may")
    return problems


def main():
    source = pathlib.Path(sys.argv[1])
    order = modules(source)
    rank = {name: i for i, name in enumerate(order)}
    problems = []

    # every public header has an owner, and includes nothing private
    for header in sorted((source / "include" / "cambrian").glob("*.hpp")):
        if header.name not in OWNER:
            problems.append(f"include/cambrian/{header.name}: no owning module in OWNER")
        for kind, name in INCLUDE.findall(header.read_text()):
            if kind == '"' and not name.startswith("cambrian/"):
                problems.append(f"include/cambrian/{header.name}: includes the private {name}")
    for name, owner in OWNER.items():
        if owner not in rank:
            problems.append(f"OWNER[{name}] = {owner}: not a module")

    # every source file: its includes stay at or below its module
    for path in sorted((source / "src").rglob("*")):
        if path.suffix not in (".cpp", ".hpp"):
            continue
        relative = path.relative_to(source / "src").as_posix()
        module = relative.split("/")[0]
        if module not in rank:
            problems.append(f"src/{relative}: in no module of CAMBRIAN_MODULES")
            continue
        text = path.read_text()
        problems += confined_problems(f"src/{relative}", text)
        for kind, name in INCLUDE.findall(text):
            if kind == '"':
                if name.startswith("cambrian/"):
                    owner = OWNER.get(name.split("/", 1)[1])
                else:
                    owner = name.split("/")[0] if "/" in name else module
                if owner is None or owner not in rank:
                    if owner is None:
                        problems.append(f"src/{relative}: includes {name}, owned by no module")
                    continue
                if rank[owner] > rank[module]:
                    problems.append(f"src/{relative}: module {module} includes {name} of the "
                                    f"higher module {owner}")

    # programs outside src/: any module's headers, third-party headers confined as in src/
    for folder in OUTSIDE_SRC:
        for path in sorted((source / folder).rglob("*")):
            if path.suffix in (".cpp", ".hpp"):
                relative = path.relative_to(source).as_posix()
                problems += confined_problems(relative, path.read_text())

    for problem in problems:
        print(problem)
    print(f"module_order_check: {len(order)} modules ({' < '.join(order)}), "
          f"{len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
