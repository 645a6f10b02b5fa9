"""The install paths of docs/cpp.md and docs/python.md, each proven in a scratch folder, offline:
`cmake --install` and a consumer project that finds mdr with find_package, `pip install` into a fresh venv,
and the .deb that cpack builds (its control fields and files, unpacked with dpkg -x and run)."""

from __future__ import annotations

import os
import pathlib
import re
import shutil
import subprocess
import sys

import pytest

SOURCE = pathlib.Path(os.environ.get("MDR_SOURCE_DIR", pathlib.Path(__file__).resolve().parents[2]))
BUILD = pathlib.Path(os.environ.get("MDR_BUILD_DIR", SOURCE / "build"))
PYTHON = os.environ.get("MDR_PYTHON", "/usr/bin/python3")
CMAKE = os.environ.get("CMAKE_COMMAND", "cmake")
CPACK = os.environ.get("CPACK_COMMAND", "cpack")
VERSION = re.search(r"project\(mdr VERSION ([0-9.]+)", (SOURCE / "CMakeLists.txt").read_text()).group(1)
CASE = SOURCE / "examples" / "default.toml"
# What a consumer of mdr::core must not need, and no installed header may include.
FOREIGN = re.compile(r"tomlplusplus|toml\+\+|nlohmann|CLI11|CLI/|pybind11")
# The packages switched off for the consumer of mdr::core and mdr::io: find_package(mdr) must need none of them.
WITHOUT_FOR_CORE = ["tomlplusplus", "nlohmann_json", "CLI11", "pybind11", "Python3", "Ceres"]


def run(*command, cwd=None, env=None) -> str:
    completed = subprocess.run([str(part) for part in command], cwd=cwd, env=env, capture_output=True, text=True)
    assert completed.returncode == 0, (f"{' '.join(map(str, command))} exited {completed.returncode}\n"
                                       f"stdout:\n{completed.stdout[-4000:]}\nstderr:\n{completed.stderr[-4000:]}")
    return completed.stdout


def clean_env(**extra: str) -> dict[str, str]:
    """The environment of a user's shell: nothing that points into the source or build tree."""
    env = {key: value for key, value in os.environ.items()
           if key not in ("PYTHONPATH", "MDR_PYTHONPATH", "MDR_BINARY", "MDR_CMAKE_BUILD_DIR")}
    env["MPLBACKEND"] = "Agg"
    env.update(extra)
    return env


def check_python_package(python: str, site: pathlib.Path, workdir: pathlib.Path, env: dict[str, str]) -> None:
    """From a folder outside the source tree: the package imports from `site`, runs a case, and plots."""
    script = (f"import mdr, pathlib\n"
              f"assert pathlib.Path(mdr.__file__).resolve().is_relative_to(pathlib.Path({str(site)!r}).resolve()), mdr.__file__\n"
              f"assert mdr.__version__ == {VERSION!r}, mdr.__version__\n"
              f"result = mdr.run({str(CASE)!r})\n"
              f"assert result.summary['max_force'] > 0, result.summary\n"
              f"print(mdr.__file__, result.summary['max_force'])\n")
    run(python, "-c", script, cwd=workdir, env=env)


def check_binary(binary: pathlib.Path, python: str, workdir: pathlib.Path, env: dict[str, str]) -> None:
    """The installed command line is the C++ binary; its result plots with `python -m mdr plot`."""
    assert binary.read_bytes()[:4] == b"\x7fELF", f"{binary}: not the compiled command line"
    assert run(binary, "--version", env=env).strip() == f"mdr {VERSION}"
    run(binary, "run", CASE, "--out", workdir / "result", cwd=workdir, env=env)
    printed = run(python, "-m", "mdr", "plot", "result", cwd=workdir, env=env)
    figures = [line for line in printed.splitlines() if line.endswith(".png")]
    assert figures and all((workdir / "result" / pathlib.Path(f).name).is_file() for f in figures), printed


def providing_packages(binary: pathlib.Path) -> dict[str, str]:
    """The shared libraries that `binary` names as NEEDED, each with the Debian package that holds it here."""
    needed = re.findall(r"\(NEEDED\)\s+Shared library: \[(.+?)\]", run("readelf", "-d", binary))
    listed = run("ldd", binary)
    resolved = dict(re.findall(r"^\s*(\S+) => (/\S+)", listed, re.MULTILINE))
    # The dynamic loader is listed by its path alone ("/lib64/ld-linux-x86-64.so.2 (0x...)"); a binary names it as
    # NEEDED when its code reads thread-local storage through __tls_get_addr (position-independent objects).
    resolved |= {pathlib.Path(path).name: path for path in re.findall(r"^\s*(/\S+) \(0x", listed, re.MULTILINE)}
    packages = {}
    for soname in needed:
        assert soname in resolved, f"{binary.name}: {soname} not found by ldd"
        real = pathlib.Path(resolved[soname]).resolve()  # alternatives (LAPACK, BLAS) to the file a package holds
        owners = subprocess.run(["dpkg", "-S", str(real), str(real).removeprefix("/usr")],
                                capture_output=True, text=True).stdout  # merged /usr: either spelling is the one
        assert owners, f"{binary.name}: no package holds {real}"
        packages[soname] = owners.split(":")[0]
    return packages


def test_cmake_package(tmp_path: pathlib.Path) -> None:
    prefix = tmp_path / "prefix"
    run(CMAKE, "--install", BUILD, "--prefix", prefix)

    for path in ["bin/mdr", "lib/libmdr_core.a", "lib/libmdr_io.a", "lib/libmdr_fit.a", "lib/libmdr_fitcase.a",
                 "include/mdr/rheology/rheology.hpp", "include/mdr/drivers/indentation.hpp",
                 "include/mdr/fit/fit.hpp", "include/mdr/fitcase/fit_case.hpp", "lib/cmake/mdr/mdrConfig.cmake",
                 "lib/cmake/mdr/mdrConfigVersion.cmake",
                 "lib/cmake/mdr/mdrTargets.cmake", "lib/cmake/mdr/mdrFitTargets.cmake",
                 "lib/python3/dist-packages/mdr/__init__.py"]:
        assert (prefix / path).is_file(), f"not installed: {path}"
    for header in (prefix / "include").rglob("*"):
        if header.is_file():
            includes = [line for line in header.read_text().splitlines() if line.startswith("#include")]
            assert not [line for line in includes if FOREIGN.search(line)], f"{header}: {includes}"
    for script in (prefix / "lib/cmake/mdr").glob("*.cmake"):
        code = "\n".join(line for line in script.read_text().splitlines() if not line.lstrip().startswith("#"))
        assert not FOREIGN.search(code), f"{script} names a dependency a consumer must not need"

    # The consumer asks only for mdr; the parsers, CLI11, Python and Ceres are switched off, so a find_dependency
    # on any of them would fail the configure.
    consumer = tmp_path / "consumer"
    run(CMAKE, "-S", SOURCE / "tests/install/consumer", "-B", consumer, f"-DCMAKE_PREFIX_PATH={prefix}",
        "-DCMAKE_BUILD_TYPE=Release", *(f"-DCMAKE_DISABLE_FIND_PACKAGE_{name}=ON" for name in WITHOUT_FOR_CORE))
    cache = (consumer / "CMakeCache.txt").read_text()
    assert f"mdr_DIR:PATH={prefix}/lib/cmake/mdr" in cache
    run(CMAKE, "--build", consumer, "-j", "2")
    assert run(consumer / "consumer").strip().endswith(f"mdr {VERSION}: ok")
    assert run(consumer / "io_consumer").strip().endswith(": ok")

    # The fitting is the component fit: with Ceres it builds and fits; without, the configure fails and says why.
    fit_consumer = tmp_path / "fit_consumer"
    run(CMAKE, "-S", SOURCE / "tests/install/fit_consumer", "-B", fit_consumer, f"-DCMAKE_PREFIX_PATH={prefix}",
        "-DCMAKE_BUILD_TYPE=Release")
    run(CMAKE, "--build", fit_consumer, "-j", "2")
    assert run(fit_consumer / "fit_consumer").strip().endswith(f"mdr::fit {VERSION}: ok")
    without_ceres = subprocess.run([CMAKE, "-S", SOURCE / "tests/install/fit_consumer", "-B", tmp_path / "no_ceres",
                                    f"-DCMAKE_PREFIX_PATH={prefix}", "-DCMAKE_DISABLE_FIND_PACKAGE_Ceres=ON"],
                                   capture_output=True, text=True)
    assert without_ceres.returncode != 0, without_ceres.stdout
    assert "component fit (mdr::fit) needs Ceres Solver" in " ".join(without_ceres.stderr.split()), without_ceres.stderr

    workdir = tmp_path / "elsewhere"
    workdir.mkdir()
    site = prefix / "lib/python3/dist-packages"
    env = clean_env(PYTHONPATH=str(site))
    check_python_package(PYTHON, site, workdir, env)
    check_binary(prefix / "bin/mdr", PYTHON, workdir, env)


def check_venv(venv: pathlib.Path, workdir: pathlib.Path) -> None:
    """What pip installed into `venv`: the package and the command line, used from `workdir`; then uninstalled."""
    python = str(venv / "bin/python")
    site = pathlib.Path(run(python, "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])").strip())
    workdir.mkdir()
    env = clean_env(PATH=f"{venv / 'bin'}{os.pathsep}{os.environ.get('PATH', '')}")
    check_python_package(python, site, workdir, env)
    check_binary(venv / "bin/mdr", python, workdir, env)
    assert run("mdr", "--version", env=env).strip() == f"mdr {VERSION}"  # the venv's, first on PATH

    run(python, "-m", "pip", "uninstall", "-y", "mdr", env=env)
    assert not (venv / "bin/mdr").exists(), "pip uninstall left bin/mdr"


def test_pip_venv(tmp_path: pathlib.Path) -> None:
    venv = tmp_path / "venv"
    run(PYTHON, "-m", "venv", "--system-site-packages", venv)
    # Offline (no index) and without build isolation; the existing build is reused (setup.py,
    # MDR_CMAKE_BUILD_DIR): without it pip configures and builds the extension and the binary afresh
    # (test_pip_from_scratch).
    run(venv / "bin/python", "-m", "pip", "install", "--no-build-isolation", "--no-deps", "--no-index",
        "--no-cache-dir", "--disable-pip-version-check", SOURCE, cwd=tmp_path,
        env=clean_env(MDR_CMAKE_BUILD_DIR=str(BUILD)))
    check_venv(venv, tmp_path / "elsewhere")


def source_copy(destination: pathlib.Path) -> pathlib.Path:
    """The source tree as a clone has it (with uncommitted edits): no build folders, results or caches
    (those of .gitignore)."""
    def ignored(folder: str, names: list[str]) -> set[str]:
        at_root = pathlib.Path(folder) == SOURCE
        return {name for name in names
                if name in ("__pycache__", ".git") or name.endswith((".pyc", ".egg-info"))
                or (at_root and (name in ("build", "out") or name.startswith("build-")))}
    shutil.copytree(SOURCE, destination, ignore=ignored, symlinks=True)
    return destination


def test_pip_from_scratch(tmp_path: pathlib.Path) -> None:
    """docs/python.md's commands as written, in a copy of the sources with no build: pip configures and builds
    the extension and the command line itself (minutes)."""
    source = source_copy(tmp_path / "mdr")
    venv = tmp_path / "venv"
    run(PYTHON, "-m", "venv", "--system-site-packages", venv)
    # ccache (which CMakeLists.txt uses where it is installed) hits across runs in different scratch folders
    # when paths are taken relative to the copy; the objects are those the compiler gives.
    env = clean_env(CCACHE_BASEDIR=str(source))
    run(venv / "bin/pip", "install", "--no-build-isolation", "--no-deps", ".", cwd=source, env=env)
    check_venv(venv, tmp_path / "elsewhere")
    shutil.rmtree(source / "build")  # hundreds of MB; pytest keeps its last scratch folders


def test_deb(tmp_path: pathlib.Path) -> None:
    run(CPACK, "-G", "DEB", "-B", tmp_path / "packages", "--config", BUILD / "CPackConfig.cmake", cwd=BUILD)
    debs = list((tmp_path / "packages").glob("*.deb"))
    assert len(debs) == 1, debs
    deb = debs[0]
    assert deb.name == f"mdr_{VERSION}_amd64.deb" or deb.name.startswith(f"mdr_{VERSION}_")

    depends = run("dpkg-deb", "-f", deb, "Depends")
    # libzip, libdeflate: the extension reads instrument files (mdr.read_curves).
    for package in ["libfmt9", "libstdc++6", "libc6", "libzip", "libdeflate", "python3-numpy", "python3 ("]:
        assert package in depends, f"Depends: {depends}"
    assert "tomli" not in depends, f"Depends: {depends} (dict cases reach the core as a tree, issue 27)"
    assert not FOREIGN.search(depends.replace("python3", "")), depends
    # Building against the package: fmt's CMake files for find_package(mdr), Ceres' for COMPONENTS fit.
    assert "libfmt-dev" in run("dpkg-deb", "-f", deb, "Recommends")
    assert "libceres-dev" in run("dpkg-deb", "-f", deb, "Suggests")

    contents = run("dpkg-deb", "-c", deb)
    listed = {line.split()[-1].removeprefix(".") for line in contents.splitlines()}
    for path in ["/usr/bin/mdr", "/usr/lib/libmdr_core.a", "/usr/lib/libmdr_io.a", "/usr/lib/libmdr_fit.a",
                 "/usr/lib/libmdr_fitcase.a",
                 "/usr/include/mdr/rheology/rheology.hpp", "/usr/lib/cmake/mdr/mdrConfig.cmake",
                 "/usr/lib/cmake/mdr/mdrConfigVersion.cmake", "/usr/lib/cmake/mdr/mdrFitTargets.cmake",
                 "/usr/lib/python3/dist-packages/mdr/__init__.py", "/usr/lib/python3/dist-packages/mdr/plot.py"]:
        assert path in listed, f"{path} not in the package:\n{contents}"
    extension = [p for p in listed if re.fullmatch(r"/usr/lib/python3/dist-packages/mdr/_mdr\..*\.so", p)]
    assert extension, contents

    root = tmp_path / "root"
    run("dpkg", "-x", deb, root)
    # Every shared library that the command line and the extension load comes with a package in Depends (or, for
    # one chosen by alternatives such as LAPACK, its soname is the virtual package there).
    for binary in [root / "usr/bin/mdr", root / extension[0].lstrip("/")]:
        for soname, package in providing_packages(binary).items():
            named = [name for name in (package, soname)
                     if re.search(rf"(^|[ ,|]){re.escape(name)}( |,|$)", depends)]
            assert named, f"{binary.name} needs {soname} ({package} here): Depends: {depends}"
    workdir = tmp_path / "elsewhere"
    workdir.mkdir()
    site = root / "usr/lib/python3/dist-packages"
    env = clean_env(PYTHONPATH=str(site))
    check_python_package(PYTHON, site, workdir, env)
    check_binary(root / "usr/bin/mdr", PYTHON, workdir, env)


if __name__ == "__main__":
    sys.exit(pytest.main([__file__, "-q"]))
