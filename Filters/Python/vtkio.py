"""Running the pipeline's VTK algorithms and reading and writing their data
for consistent-remesh: every failure is a StageError whose message says
what went wrong."""

import csv

from vtkmodules.util.misc import calldata_type
from vtkmodules.util.vtkConstants import VTK_STRING
from vtkmodules.vtkCommonCore import vtkCommand
from vtkmodules.vtkIOXML import vtkXMLMultiBlockDataWriter, vtkXMLPolyDataReader, vtkXMLPolyDataWriter


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
    _write_xml(vtkXMLPolyDataWriter(), polydata, path)


def write_multiblock(data, path):
    """Writes PATH.vtm and its pieces in a folder PATH without the extension."""
    _write_xml(vtkXMLMultiBlockDataWriter(), data, path)


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
