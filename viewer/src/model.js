// The model's data as the C++ export writes it into the page (nodes/export/assembly_html.h):
// packed and integer coordinates are turned into millimetres, and pieces are indexed by name.

// Little-endian unsigned integers of `bytes` bytes each, from base64.
function unpack(base64, bytes) {
  const binary = atob(base64);
  const view = new DataView(new ArrayBuffer(binary.length));
  for (let i = 0; i < binary.length; ++i) view.setUint8(i, binary.charCodeAt(i));
  const values = new Uint32Array(binary.length / bytes);
  for (let i = 0; i < values.length; ++i)
    values[i] = bytes === 2 ? view.getUint16(2 * i, true) : view.getUint32(4 * i, true);
  return values;
}

// The page's data: gzip-compressed JSON in base64, opened by the browser's own gunzip.
export async function dataText(base64) {
  const bytes = Uint8Array.from(atob(base64.trim()), (c) => c.charCodeAt(0));
  const stream = new Blob([bytes]).stream().pipeThrough(new DecompressionStream('gzip'));
  return new Response(stream).text();
}

export function readModel(text) {
  const data = JSON.parse(text);
  const { origin, step } = data.grid;
  const pieces = data.pieces.map((piece, index) => {
    const grid = unpack(piece.points, 2);
    const points = new Float32Array(grid.length);
    for (let i = 0; i < points.length; ++i) points[i] = origin[i % 3] + grid[i] * step;
    return {
      index,
      name: piece.name,
      page: piece.page,
      step: piece.step,
      part: piece.part,
      colour: piece.colour,
      points,
      triangles: unpack(piece.triangles, piece.index_bytes),
      outline: piece.outline.map((loop) => loop.map((v) => v / 10)),  // 0.1 mm
      number: piece.number.map((v) => v / 10),
      seams: piece.seams.map((seam) => ({
        label: seam.label,
        partner: seam.partner,
        edges: seam.edges,
        boxes: seam.boxes.map((box) => ({
          x: box[0] / 10, y: box[1] / 10, angle: box[2], size: box[3] / 10,
        })),
      })),
    };
  });
  const byName = new Map(pieces.map((piece) => [piece.name, piece]));
  const steps = data.steps.map((step, index) => ({
    number: index + 1,
    piece: byName.get(step.piece),
    text: step.text,
    labels: step.seams,
  }));
  return {
    name: data.name,
    page: data.page,
    pageCount: data.page_count,
    parts: data.parts,
    notes: data.notes,
    svgPages: data.pages_svg,
    pieces,
    byName,
    steps,
  };
}
