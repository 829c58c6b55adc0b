"""The PEP 517 / PEP 660 build backend of rotorcert-vectors, standard library only.

Why not setuptools (pyproject.toml says it too): before version 70.1 setuptools builds a wheel only
through the separate `wheel` distribution, and neither Debian 12's python3-venv environments
(setuptools 66.1) nor Python 3.11's own ensurepip (setuptools 65.5) carry it; pip would then have
to download build requirements, and `pip install conformance/packages/python` must work offline.
A pure-Python package needs no compiler, so the backend is small: it reads the [project] table of
pyproject.toml (PEP 621: name, version, description, readme, requires-python, dependencies,
keywords, classifiers, scripts, entry-points) and [tool.rotorcert-build] packages (import packages
under src/), and writes

  - a wheel (PEP 427): the packages, METADATA (core metadata 2.1), WHEEL, entry_points.txt, RECORD;
  - an editable wheel (PEP 660): a .pth file naming src/, for `pip install -e`;
  - an sdist (PEP 517/625): pyproject.toml, README, build_backend/, src/, PKG-INFO.

Archives are reproducible: files sorted, timestamps from SOURCE_DATE_EPOCH (default 1980-01-01),
modes 0644. Nothing is written into the source tree.
"""
import base64
import csv
import gzip
import hashlib
import io
import os
import re
import tarfile
import time
import zipfile

try:
    import tomllib
except ImportError:  # Python < 3.11
    try:
        import tomli as tomllib
    except ImportError:
        tomllib = None

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SKIPPED_DIRS = {"__pycache__"}
SKIPPED_SUFFIXES = (".pyc", ".pyo")


class Project:
    """What pyproject.toml says about the distribution."""

    def __init__(self, root=ROOT):
        if tomllib is None:
            raise RuntimeError("rotorcert-vectors' build backend reads pyproject.toml with tomllib "
                               "(Python 3.11+) or tomli; install tomli or use Python 3.11")
        with open(os.path.join(root, "pyproject.toml"), "rb") as f:
            data = tomllib.load(f)
        self.root = root
        self.meta = data["project"]
        self.name = self.meta["name"]
        self.version = self.meta["version"]
        self.dist = re.sub(r"[-_.]+", "_", self.name).lower()  # PEP 427/625 file-name form
        self.packages = data.get("tool", {}).get("rotorcert-build", {}).get("packages", [])
        if not self.packages:
            raise RuntimeError("pyproject.toml: [tool.rotorcert-build] packages is empty")
        self.src = os.path.join(root, "src")

    @property
    def dist_info(self):
        return "%s-%s.dist-info" % (self.dist, self.version)

    def readme(self):
        readme = self.meta.get("readme")
        if not readme:
            return None, ""
        path = readme if isinstance(readme, str) else readme["file"]
        kind = "text/markdown" if path.endswith(".md") else "text/x-rst" if path.endswith(".rst") else "text/plain"
        with open(os.path.join(self.root, path), encoding="utf-8") as f:
            return kind, f.read()

    def metadata(self):
        """Core metadata 2.1 (METADATA in a wheel, PKG-INFO in an sdist)."""
        lines = ["Metadata-Version: 2.1", "Name: " + self.name, "Version: " + self.version]
        if self.meta.get("description"):
            lines.append("Summary: " + self.meta["description"])
        if self.meta.get("keywords"):
            lines.append("Keywords: " + ",".join(self.meta["keywords"]))
        for c in self.meta.get("classifiers", []):
            lines.append("Classifier: " + c)
        if self.meta.get("requires-python"):
            lines.append("Requires-Python: " + self.meta["requires-python"])
        for d in self.meta.get("dependencies", []):
            lines.append("Requires-Dist: " + d)
        kind, text = self.readme()
        if kind:
            lines.append("Description-Content-Type: " + kind)
        return "\n".join(lines) + "\n\n" + text

    def entry_points(self):
        groups = {}
        if self.meta.get("scripts"):
            groups["console_scripts"] = self.meta["scripts"]
        if self.meta.get("gui-scripts"):
            groups["gui_scripts"] = self.meta["gui-scripts"]
        groups.update(self.meta.get("entry-points", {}))
        if not groups:
            return None
        out = []
        for group, entries in groups.items():
            out.append("[%s]" % group)
            out.extend("%s = %s" % kv for kv in entries.items())
            out.append("")
        return "\n".join(out)

    def package_files(self):
        """(path in the wheel, path on disk) of every file of the import packages, sorted."""
        files = []
        for package in self.packages:
            top = os.path.join(self.src, *package.split("."))
            if not os.path.isfile(os.path.join(top, "__init__.py")):
                raise RuntimeError("src/%s is not an import package (no __init__.py)" % package.replace(".", "/"))
            for dirpath, dirnames, filenames in os.walk(top):
                dirnames[:] = sorted(d for d in dirnames if d not in SKIPPED_DIRS)
                for fn in filenames:
                    if fn.endswith(SKIPPED_SUFFIXES):
                        continue
                    disk = os.path.join(dirpath, fn)
                    files.append((os.path.relpath(disk, self.src).replace(os.sep, "/"), disk))
        return sorted(files)

    def dist_info_files(self, editable=False):
        files = {"METADATA": self.metadata(),
                 "WHEEL": "Wheel-Version: 1.0\nGenerator: rotorcert_vectors_build\nRoot-Is-Purelib: true\n"
                          "Tag: py3-none-any\n"}
        ep = self.entry_points()
        if ep:
            files["entry_points.txt"] = ep
        return {self.dist_info + "/" + name: text.encode("utf-8") for name, text in files.items()}


def _timestamp():
    return int(os.environ.get("SOURCE_DATE_EPOCH", "315532800"))  # 1980-01-01, zip's earliest


def _write_wheel(project, wheel_directory, payload):
    """payload: {path in the wheel: bytes}; RECORD is added last (PEP 427)."""
    name = "%s-%s-py3-none-any.whl" % (project.dist, project.version)
    record_path = project.dist_info + "/RECORD"
    records = []
    date = time.gmtime(max(_timestamp(), 315532800))[:6]
    tmp = os.path.join(wheel_directory, name + ".tmp")
    with zipfile.ZipFile(tmp, "w", zipfile.ZIP_DEFLATED) as zf:
        for path in sorted(payload):
            data = payload[path]
            info = zipfile.ZipInfo(path, date)
            info.external_attr = 0o644 << 16
            info.compress_type = zipfile.ZIP_DEFLATED
            zf.writestr(info, data)
            digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=").decode()
            records.append((path, "sha256=" + digest, str(len(data))))
        records.append((record_path, "", ""))
        out = io.StringIO()
        csv.writer(out, lineterminator="\n").writerows(records)
        info = zipfile.ZipInfo(record_path, date)
        info.external_attr = 0o644 << 16
        info.compress_type = zipfile.ZIP_DEFLATED
        zf.writestr(info, out.getvalue().encode("utf-8"))
    os.replace(tmp, os.path.join(wheel_directory, name))
    return name


def _write_metadata_dir(project, metadata_directory):
    for path, data in project.dist_info_files().items():
        target = os.path.join(metadata_directory, *path.split("/"))
        os.makedirs(os.path.dirname(target), exist_ok=True)
        with open(target, "wb") as f:
            f.write(data)
    return project.dist_info


# ---- PEP 517 hooks ---------------------------------------------------------------------------

def get_requires_for_build_wheel(config_settings=None):
    return []


def get_requires_for_build_sdist(config_settings=None):
    return []


def get_requires_for_build_editable(config_settings=None):
    return []


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    return _write_metadata_dir(Project(), metadata_directory)


def prepare_metadata_for_build_editable(metadata_directory, config_settings=None):
    return _write_metadata_dir(Project(), metadata_directory)


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    project = Project()
    payload = project.dist_info_files()
    for path, disk in project.package_files():
        with open(disk, "rb") as f:
            payload[path] = f.read()
    return _write_wheel(project, wheel_directory, payload)


def build_editable(wheel_directory, config_settings=None, metadata_directory=None):
    """PEP 660: the packages stay in src/; a .pth file puts src/ on sys.path."""
    project = Project()
    payload = project.dist_info_files()
    payload["__editable__.%s-%s.pth" % (project.dist, project.version)] = (project.src + "\n").encode("utf-8")
    return _write_wheel(project, wheel_directory, payload)


def build_sdist(sdist_directory, config_settings=None):
    project = Project()
    base = "%s-%s" % (project.dist, project.version)
    members = [("pyproject.toml", os.path.join(project.root, "pyproject.toml"))]
    kind, _ = project.readme()
    if kind:
        readme = project.meta["readme"]
        path = readme if isinstance(readme, str) else readme["file"]
        members.append((path, os.path.join(project.root, path)))
    backend = os.path.join(project.root, "build_backend", "rotorcert_vectors_build.py")
    members.append(("build_backend/rotorcert_vectors_build.py", backend))
    members += [("src/" + path, disk) for path, disk in project.package_files()]
    name = base + ".tar.gz"
    mtime = _timestamp()

    def add(tar, arcname, data):
        info = tarfile.TarInfo(base + "/" + arcname)
        info.size, info.mtime, info.mode = len(data), mtime, 0o644
        info.uid = info.gid = 0
        info.uname = info.gname = ""
        tar.addfile(info, io.BytesIO(data))

    tmp = os.path.join(sdist_directory, name + ".tmp")
    with open(tmp, "wb") as raw, gzip.GzipFile(fileobj=raw, mode="wb", mtime=mtime, filename="") as gz, \
            tarfile.open(fileobj=gz, mode="w", format=tarfile.PAX_FORMAT) as tar:
        for arcname, disk in sorted(members):
            with open(disk, "rb") as f:
                add(tar, arcname, f.read())
        add(tar, "PKG-INFO", project.metadata().encode("utf-8"))
    os.replace(tmp, os.path.join(sdist_directory, name))
    return name
