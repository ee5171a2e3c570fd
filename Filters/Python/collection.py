"""Collections described by a collection.json: the meshes (read from a
Debian package's archive), their landmark files, a base domain and the
stages to run. `consistent-remesh` with no --mesh runs the default one, the
CGAL quadrupeds of Data/cgal-quadrupeds, which the package carries in
consistent_mesh/data.

collection.json:
  title, description        text for the report
  archive.package           the Debian package that installs the archive
  archive.paths             where the archive may be (the first that exists)
  models[]: name, member    the mesh's path inside the archive
            landmarks       landmark file, relative to the folder
            sha256          of the mesh as unpacked: a changed package is an error
  base_domain               relative to the folder
  stages                    level, relax_samples, pca, blend, blend_alignment, transfer_from, view_up

The meshes are unpacked once into a cache folder ($CMP_CACHE_DIR, else
$XDG_CACHE_HOME/consistent-mesh, else ~/.cache/consistent-mesh) and checked
against their SHA-256 every run. $CMP_CGAL_DATA_ARCHIVE, when set, is the
archive, whatever archive.paths say (see Data/cgal-quadrupeds/README.md for
slim container images).
"""

import hashlib
import json
import os
import re
import tarfile
import tempfile
import zlib

MANIFEST = "collection.json"
DEFAULT_COLLECTION = "cgal-quadrupeds"
ARCHIVE_VARIABLE = "CMP_CGAL_DATA_ARCHIVE"


class CollectionError(Exception):
    """A collection cannot be used; the message says why and what to do."""


def default_folder():
    """The default collection's folder inside the package."""
    return os.path.join(os.path.dirname(os.path.abspath(__file__)), "data", DEFAULT_COLLECTION)


def cache_folder():
    """Where unpacked meshes are kept between runs."""
    if os.environ.get("CMP_CACHE_DIR"):
        return os.environ["CMP_CACHE_DIR"]
    base = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    return os.path.join(base, "consistent-mesh")


class Collection:
    """A collection.json read and checked: its models' mesh paths (in the
    cache) and landmark paths, its base domain and its stages."""

    def __init__(self, folder):
        self.folder = os.path.abspath(folder)
        path = os.path.join(self.folder, MANIFEST)
        try:
            with open(path) as manifest:
                description = json.load(manifest)
        except OSError as error:
            raise CollectionError("cannot read the collection description %s: %s" % (path, error.strerror))
        except ValueError as error:
            raise CollectionError("%s is not valid JSON: %s" % (path, error))
        entry = _Entries(path)
        root = entry.of(description, dict, "the file")
        self.title = entry.of(root.get("title"), str, "title")
        self.description = entry.of(root.get("description", ""), str, "description")
        archive = entry.of(root.get("archive"), dict, "archive")
        self.package = entry.of(archive.get("package"), str, "archive.package")
        self.archive_paths = [entry.of(p, str, "archive.paths[]") for p in entry.of(archive.get("paths"), list,
                                                                                       "archive.paths")]
        self.models = []
        for index, model in enumerate(entry.of(root.get("models"), list, "models")):
            where = "models[%d]" % index
            model = entry.of(model, dict, where)
            name = entry.of(model.get("name"), str, where + ".name")
            # Names make file names in the cache and the output folder.
            if not name or "/" in name or name.startswith("."):
                raise CollectionError("%s: %s.name %r cannot name a file" % (path, where, name))
            digest = entry.of(model.get("sha256"), str, where + ".sha256").lower()
            if not re.fullmatch("[0-9a-f]{64}", digest):
                raise CollectionError("%s: %s.sha256 is not 64 hexadecimal digits" % (path, where))
            self.models.append((name, entry.of(model.get("member"), str, where + ".member"),
                                entry.of(model.get("landmarks"), str, where + ".landmarks"), digest))
        if not self.models:
            raise CollectionError("%s lists no models" % path)
        names = [name for name, _, _, _ in self.models]
        if len(set(names)) != len(names):
            raise CollectionError("%s: two models share a name" % path)
        self.base_domain = os.path.join(self.folder, entry.of(root.get("base_domain"), str, "base_domain"))
        self.stages = _checked_stages(entry, entry.of(root.get("stages", {}), dict, "stages"), names)
        self.cache = os.path.join(cache_folder(), os.path.basename(self.folder))

    def mesh_paths(self):
        """Where each model's mesh is once unpacked (named after the model,
        which is what names its results)."""
        return [os.path.join(self.cache, name + os.path.splitext(member)[1]) for name, member, _, _ in self.models]

    def landmark_paths(self):
        return [os.path.join(self.folder, landmarks) for _, _, landmarks, _ in self.models]

    def find_archive(self):
        """The archive's path, or CollectionError naming the package to
        install."""
        override = os.environ.get(ARCHIVE_VARIABLE)
        candidates = [override] if override else self.archive_paths
        for candidate in candidates:
            if os.path.isfile(candidate):
                return candidate
        if override:
            raise CollectionError("%s=%s: no such file" % (ARCHIVE_VARIABLE, override))
        raise CollectionError(
            "the collection's meshes come from Debian's %s package, and %s is not there: install it "
            "(apt-get install %s; ./setup.sh does), set %s to its data.tar.gz, or give your own models with "
            "--mesh and --landmarks" % (self.package, " or ".join(self.archive_paths), self.package,
                                        ARCHIVE_VARIABLE))

    def unpack(self, progress=print):
        """Unpacks the meshes that are not in the cache yet (or no longer
        match their SHA-256) and returns their paths."""
        paths = self.mesh_paths()
        wanted = {member: (path, digest) for (_, member, _, digest), path in zip(self.models, paths)
                  if _sha256(path) != digest}
        if wanted:
            archive = self.find_archive()
            progress("unpacking %d mesh%s from %s into %s"
                     % (len(wanted), "" if len(wanted) == 1 else "es", archive, self.cache))
            _extract(archive, wanted, self.cache)
        # Only what was just unpacked needs checking again.
        for member, (path, digest) in wanted.items():
            if _sha256(path) != digest:
                raise CollectionError("%s in %s is not the mesh this collection's landmarks were picked on (its "
                                      "SHA-256 differs): the package has changed" % (member, self.package))
        return paths


class _Entries:
    """Type checks of a collection.json's entries, with errors naming the
    file and the entry."""

    def __init__(self, path):
        self.path = path

    def of(self, value, kind, where):
        # bool is an int to Python, never to a collection.json.
        if value is None or not isinstance(value, kind) or (kind is int and isinstance(value, bool)):
            raise CollectionError("%s: %s is %s, not %s" % (self.path, where, "missing" if value is None else
                                                           "a " + type(value).__name__, _KINDS[kind]))
        return value


_KINDS = {dict: "an object", list: "a list", str: "a string", int: "a whole number", bool: "true or false"}
_STAGES = {"level": int, "relax_samples": int, "pca": int, "blend": bool, "blend_alignment": str,
           "transfer_from": str, "view_up": str}


def _checked_stages(entry, stages, names):
    """The stages of a collection.json, each of the right kind; the command
    line checks their ranges as for its own options."""
    for key, value in stages.items():
        if key not in _STAGES:
            raise CollectionError("%s: stages.%s is not a stage (%s are)" % (entry.path, key, ", ".join(_STAGES)))
        entry.of(value, _STAGES[key], "stages." + key)
    if stages.get("transfer_from") is not None and stages["transfer_from"] not in names:
        raise CollectionError("%s: stages.transfer_from %s is none of the models" % (entry.path,
                                                                                     stages["transfer_from"]))
    return dict(stages)


def _sha256(path):
    """The file's SHA-256 in hex, or None if it cannot be read."""
    digest = hashlib.sha256()
    try:
        with open(path, "rb") as data:
            for block in iter(lambda: data.read(1 << 20), b""):
                digest.update(block)
    except OSError:
        return None
    return digest.hexdigest()


def _extract(archive, wanted, folder):
    """Copies the archive members `wanted` (member -> (path, _)) to their
    paths, each through a temporary file so that an interrupted run leaves
    no half mesh behind; one pass over the compressed archive."""
    remaining = dict(wanted)
    try:
        os.makedirs(folder, exist_ok=True)
        with tarfile.open(archive, "r:*") as tar:
            for member in tar:
                if member.name not in remaining:
                    continue
                path, _ = remaining.pop(member.name)
                source = tar.extractfile(member)
                if source is None:
                    raise CollectionError("%s in %s is not a file" % (member.name, archive))
                _write_atomically(path, source.read())
                if not remaining:
                    break
    # A truncated gzip stream ends in EOFError or zlib.error, not TarError.
    except (OSError, EOFError, zlib.error, tarfile.TarError) as error:
        raise CollectionError("cannot unpack the meshes from %s into %s: %s" % (archive, folder, error))
    if remaining:
        raise CollectionError("%s has no %s" % (archive, ", ".join(sorted(remaining))))


def _write_atomically(path, content):
    """`content` into `path` through a temporary file beside it, readable by
    all as a cache shared between users must be; no temporary file is left
    if writing fails."""
    handle, temporary = tempfile.mkstemp(dir=os.path.dirname(path), suffix=".part")
    try:
        with os.fdopen(handle, "wb") as out:
            out.write(content)
        umask = os.umask(0)
        os.umask(umask)
        os.chmod(temporary, 0o666 & ~umask)
        os.replace(temporary, path)
    except BaseException:
        if os.path.exists(temporary):
            os.remove(temporary)
        raise
