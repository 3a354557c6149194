//! ParaView's partitioned `.pvtu` (`PUnstructuredGrid`): an XML index naming one `.vtu`
//! file per piece (`<Piece Source="..."/>`), as VTK's parallel writers and ParaView's
//! "Save Data" with several ranks write it. Every piece is read by the `.vtu` reader into
//! one mesh, the interface vertices each piece repeats identified by their exact
//! coordinates ([`super::vtu`]'s `Merged`): the mesh checked is the merged one.
//!
//! A piece's `Source` must be a relative path inside the `.pvtu`'s folder (no `..`, no
//! absolute path): a hostile index cannot make the reader open another file. A missing
//! or unreadable piece is an error naming it.

use super::vtu::{Merged, absorb_file, decode_file};
use super::{Input, InputError, read_bytes};
use quick_xml::events::Event;
use rayon::prelude::*;
use std::path::{Component, Path, PathBuf};

/// Reads the pieces a few files at a time: each file decoded on its own thread, then
/// merged in order (the same mesh, and the same first error, as one file after another;
/// the memory of the merged mesh and of as many decoded files as there are threads).
pub(super) fn read(path: &Path) -> Result<Input, InputError> {
    let mut merged = Merged::new(path);
    let files = piece_files(path)?;
    for some in files.chunks(rayon::current_num_threads().max(1)) {
        let decoded: Vec<_> = some.par_iter().map(|f| decode_file(f)).collect();
        for (file, pieces) in some.iter().zip(decoded) {
            absorb_file(file, pieces, &mut merged)?;
        }
    }
    merged.finish(path)
}

/// The piece files the `.pvtu` at `path` names, each checked to be inside its folder.
pub(super) fn piece_files(path: &Path) -> Result<Vec<PathBuf>, InputError> {
    let folder = path.parent().unwrap_or(Path::new(""));
    let mut files = Vec::new();
    for (line, source) in sources(path)? {
        let inside = Path::new(&source)
            .components()
            .all(|c| matches!(c, Component::Normal(_) | Component::CurDir));
        if !inside || source.is_empty() {
            let why = format!("piece Source \"{source}\" is not a file inside the .pvtu's folder");
            return Err(InputError::new(path, line, why));
        }
        files.push(folder.join(source));
    }
    Ok(files)
}

/// The `Source` of every `Piece` of the index, with its line.
fn sources(path: &Path) -> Result<Vec<(usize, String)>, InputError> {
    let bytes = read_bytes(path)?;
    let text =
        std::str::from_utf8(&bytes).map_err(|_| InputError::new(path, 0, "not UTF-8 text"))?;
    let line = |pos: usize| text[..pos.min(text.len())].matches('\n').count() + 1;
    let mut reader = quick_xml::Reader::from_str(text);
    let (mut pieces, mut grid) = (Vec::new(), false);
    loop {
        let pos = reader.buffer_position() as usize;
        match reader.read_event() {
            Ok(Event::Start(e)) | Ok(Event::Empty(e)) => match e.name().as_ref() {
                b"PUnstructuredGrid" => grid = true,
                b"Piece" if grid => {
                    let source = e
                        .try_get_attribute("Source")
                        .ok()
                        .flatten()
                        .and_then(|a| a.unescape_value().ok().map(|v| v.into_owned()));
                    let Some(source) = source else {
                        return Err(InputError::new(path, line(pos), "a Piece without Source"));
                    };
                    pieces.push((line(pos), source));
                }
                _ => {}
            },
            Ok(Event::Eof) => break,
            Ok(_) => {}
            Err(e) => {
                return Err(InputError::new(
                    path,
                    line(pos),
                    format!("not well-formed XML: {e}"),
                ));
            }
        }
    }
    if !grid {
        return Err(InputError::new(
            path,
            0,
            "no PUnstructuredGrid element: not a partitioned unstructured grid",
        ));
    }
    if pieces.is_empty() {
        return Err(InputError::new(
            path,
            0,
            "a PUnstructuredGrid without a Piece",
        ));
    }
    Ok(pieces)
}

/// The `.pvtu` index of `pieces` (file names in the same folder).
pub(super) fn index_text(pieces: &[PathBuf]) -> String {
    let mut s = String::from(
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"PUnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n  <PUnstructuredGrid GhostLevel=\"0\">\n    <PPoints>\n      <PDataArray type=\"Float64\" NumberOfComponents=\"3\"/>\n    </PPoints>\n",
    );
    for p in pieces {
        let name = p
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        s.push_str(&format!("    <Piece Source=\"{name}\"/>\n"));
    }
    s.push_str("  </PUnstructuredGrid>\n</VTKFile>\n");
    s
}
