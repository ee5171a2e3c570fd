"""Running the pipeline's VTK algorithms and reading and writing their data
for consistent-remesh: every failure is a StageError whose message says
what went wrong."""

import csv

from vtkmodules.util.misc import calldata_type
from vtkmodules.util.vtkConstants import VTK_STRING
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkCommonDataModel import vtkFieldData, vtkMultiBlockDataSet
from vtkmodules.vtkIOXML import vtkXMLMultiBlockDataWriter, vtkXMLPolyDataReader, vtkXMLPolyDataWriter

from .array_names import TIMING_FIELDS

# Whether the files written keep the filters' timing field arrays
# (array_names.TIMING_FIELDS). Off, the default, a run's files are the same
# byte for byte from run to run; consistent-remesh --timing-arrays turns it on.
_keep_timing_arrays = False


def keep_timing_arrays(keep):
    """Whether write_polydata and write_multiblock keep the timing field
    arrays (off by default)."""
    global _keep_timing_arrays
    _keep_timing_arrays = bool(keep)


class StageError(Exception):
    """A pipeline stage failed on one model; the message says why."""


def run(algorithm):
    """Updates `algorithm` and returns its output, or raises StageError with
    the algorithm's own error message."""
    errors = []

    @calldata_type(VTK_STRING)
    def on_error(_obj, _event, message):
        errors.append(str(message).strip())

    tag = algorithm.AddObserver(vtkCommand.ErrorEvent, on_error)
    try:
        ok = algorithm.GetExecutive().Update()
    finally:
        algorithm.RemoveObserver(tag)
    if errors or not ok:
        raise StageError(_last_line(errors[0]) if errors else "%s failed" % algorithm.GetClassName())
    return algorithm.GetOutputDataObject(0)


def _last_line(message):
    """VTK prefixes errors with 'ERROR: In file, line N / vtkX (0x..): '."""
    lines = [line for line in message.splitlines() if line.strip()]
    text = lines[-1] if lines else message
    marker = "): "
    return text.split(marker, 1)[1] if text.startswith("vtk") and marker in text else text


def read_polydata(path):
    reader = vtkXMLPolyDataReader()
    reader.SetFileName(path)
    return run(reader)


def _write_xml(writer, data, path):
    """Binary, not appended mode (see Documentation/known-issues.md)."""
    writer.SetFileName(path)
    writer.SetInputData(data)
    writer.SetDataModeToBinary()
    # VTK 9.2's XML writers return 1 even when the file cannot be opened;
    # the error code tells.
    if not writer.Write() or writer.GetErrorCode():
        raise StageError("cannot write '%s'" % path)


def write_polydata(polydata, path):
    _write_xml(vtkXMLPolyDataWriter(), polydata if _keep_timing_arrays else without_timings(polydata), path)


def write_multiblock(data, path):
    """Writes PATH.vtm and its pieces in a folder PATH without the extension."""
    _write_xml(vtkXMLMultiBlockDataWriter(), data if _keep_timing_arrays else without_timings(data), path)


def without_timings(data):
    """`data` without the field arrays of TIMING_FIELDS, for writing; `data`
    itself is left as it is. A data set that has some comes back as a
    shallow copy (arrays shared), a multiblock as a new one around such
    copies of its blocks, names kept; anything else as it is."""
    if data is None:
        return None
    if isinstance(data, vtkMultiBlockDataSet):
        copy = vtkMultiBlockDataSet()
        copy.SetNumberOfBlocks(data.GetNumberOfBlocks())
        for index in range(data.GetNumberOfBlocks()):
            copy.SetBlock(index, without_timings(data.GetBlock(index)))
            if data.HasMetaData(index):
                copy.GetMetaData(index).Copy(data.GetMetaData(index))
        copy.SetFieldData(_fields_without_timings(data.GetFieldData()))
        return copy
    fields = data.GetFieldData()
    if fields is None or not any(fields.GetAbstractArray(i).GetName() in TIMING_FIELDS
                                 for i in range(fields.GetNumberOfArrays())):
        return data
    copy = data.NewInstance()
    copy.ShallowCopy(data)
    copy.SetFieldData(_fields_without_timings(fields))
    return copy


def _fields_without_timings(fields):
    kept = vtkFieldData()
    if fields is not None:
        for index in range(fields.GetNumberOfArrays()):
            array = fields.GetAbstractArray(index)
            if array.GetName() not in TIMING_FIELDS:
                kept.AddArray(array)
    return kept


def write_table(table, path):
    """A vtkTable as CSV, a header of the column names, numbers at full
    precision."""
    columns = [table.GetColumn(c) for c in range(table.GetNumberOfColumns())]
    try:
        with open(path, "w", newline="") as out:
            writer = csv.writer(out)
            writer.writerow([column.GetName() for column in columns])
            for row in range(table.GetNumberOfRows()):
                writer.writerow([_csv_value(column.GetValue(row)) for column in columns])
    except OSError as error:
        raise StageError("cannot write '%s': %s" % (path, error))


def _csv_value(value):
    return repr(value) if isinstance(value, float) else value
