// The page view: the pattern pages (the embedded SVG pages, or the pieces' outlines where the
// export left the pages out), each with an overlay of clickable piece outlines and seam labels.

const SVG = 'http://www.w3.org/2000/svg';

function svgElement(name, attributes) {
  const element = document.createElementNS(SVG, name);
  for (const [key, value] of Object.entries(attributes)) element.setAttribute(key, value);
  return element;
}

function outlinePath(outline) {
  return outline
    .map((loop) => {
      let d = '';
      for (let i = 0; i < loop.length; i += 2) d += `${i ? 'L' : 'M'}${loop[i]},${loop[i + 1]}`;
      return `${d}Z`;
    })
    .join('');
}

export class PageView {
  // handlers: pick(name), hoverLabel({piece, seam} | null)
  constructor(container, model, handlers) {
    this.container = container;
    this.model = model;
    this.handlers = handlers;
    this.outlines = new Map();  // piece name -> overlay path
    this.labels = [];  // {piece, seam, rect}
    this.pageElements = [];
    const { width_mm: width, height_mm: height } = model.page;
    for (let page = 1; page <= model.pageCount; ++page) {
      const element = document.createElement('div');
      element.className = 'page';
      element.style.aspectRatio = `${width} / ${height}`;
      element.dataset.page = String(page);
      const svgText = model.svgPages[page - 1];
      if (svgText) {
        const image = document.createElement('img');
        image.alt = `page ${page}`;
        image.src = URL.createObjectURL(new Blob([svgText], { type: 'image/svg+xml' }));
        element.append(image);
      }
      const overlay = svgElement('svg', { class: svgText ? 'overlay' : 'overlay drawn', viewBox: `0 0 ${width} ${height}`, preserveAspectRatio: 'none' });
      element.append(overlay);
      const caption = document.createElement('div');
      caption.className = 'caption';
      caption.textContent = `page ${page} of ${model.pageCount}`;
      element.append(caption);
      container.append(element);
      this.pageElements.push({ element, overlay, drawn: !svgText });
    }
    this.fitWidth();
    new ResizeObserver(() => this.fitWidth()).observe(container);
    for (const piece of model.pieces) this.addPiece(piece);
    for (const piece of model.pieces) this.addLabels(piece);
  }

  fitWidth() {
    const available = this.container.clientWidth - 20;
    for (const { element } of this.pageElements) element.style.width = `${Math.max(120, available)}px`;
  }

  addPiece(piece) {
    const page = this.pageElements[piece.page - 1];
    if (!page) return;
    const d = outlinePath(piece.outline);
    if (page.drawn)
      page.overlay.append(svgElement('path', { d, fill: piece.colour, 'fill-rule': 'evenodd', stroke: '#333', 'stroke-width': 0.3, 'pointer-events': 'none' }));
    const path = svgElement('path', { class: 'piece', d, 'fill-rule': 'evenodd' });
    path.dataset.piece = piece.name;
    path.addEventListener('click', () => this.handlers.pick(piece.name));
    page.overlay.append(path);
    this.outlines.set(piece.name, path);
    if (page.drawn) {
      const number = svgElement('text', { x: piece.number[0], y: piece.number[1], 'font-size': 5 });
      number.textContent = piece.name;
      page.overlay.append(number);
    }
  }

  // A box over every printed seam label: hovering it shows the partner, clicking picks the piece.
  addLabels(piece) {
    const page = this.pageElements[piece.page - 1];
    if (!page) return;
    for (const seam of piece.seams) {
      for (const box of seam.boxes) {
        const width = 0.62 * box.size * seam.label.length + 0.6;
        const height = 1.2 * box.size;
        const rect = svgElement('rect', {
          class: 'label', x: box.x - width / 2, y: box.y - height / 2, width, height,
          transform: `rotate(${box.angle} ${box.x} ${box.y})`,
        });
        rect.dataset.piece = piece.name;
        rect.dataset.label = seam.label;
        rect.addEventListener('mouseenter', (event) => this.handlers.hoverLabel({ piece, seam }, event));
        rect.addEventListener('mousemove', (event) => this.handlers.hoverLabel({ piece, seam }, event));
        rect.addEventListener('mouseleave', () => this.handlers.hoverLabel(null));
        rect.addEventListener('click', () => this.handlers.pick(piece.name));
        if (page.drawn) {
          const text = svgElement('text', { x: box.x, y: box.y, 'font-size': box.size, transform: `rotate(${box.angle} ${box.x} ${box.y})` });
          text.textContent = seam.label;
          page.overlay.append(text);
        }
        page.overlay.append(rect);
        this.labels.push({ piece, seam, rect });
      }
    }
  }

  select(name, scroll) {
    for (const [piece, path] of this.outlines) path.classList.toggle('selected', piece === name);
    const path = this.outlines.get(name);
    if (path && scroll) path.scrollIntoView({ block: 'center', inline: 'nearest' });
  }

  showStep(step, gluedLabels) {
    for (const piece of this.model.pieces) {
      const path = this.outlines.get(piece.name);
      if (!path) continue;
      path.classList.toggle('later', piece.step > step);
      path.classList.toggle('current', piece.step === step);
    }
    const current = this.model.steps[step - 1];
    for (const { piece, seam, rect } of this.labels)
      rect.classList.toggle('glue', Boolean(current) && gluedLabels.has(seam.label) &&
        (piece === current.piece || seam.partner === current.piece.name));
  }

  // The partner side of a hovered label (same label on the piece across), or none.
  showPartner(hovered) {
    for (const { piece, seam, rect } of this.labels) {
      rect.classList.toggle('hovered', Boolean(hovered) && piece === hovered.piece && seam.label === hovered.seam.label);
      rect.classList.toggle('partner', Boolean(hovered) && piece.name === hovered.seam.partner &&
        seam.label === hovered.seam.label && piece !== hovered.piece);
    }
    for (const [name, path] of this.outlines)
      path.classList.toggle('partner', Boolean(hovered) && name === hovered.seam.partner && name !== hovered.piece.name);
  }

  // Where the piece's printed number lies in the window, after scrolling its page into view.
  pointOf(name) {
    const piece = this.model.byName.get(name);
    const page = piece && this.pageElements[piece.page - 1];
    if (!page) return null;
    const path = this.outlines.get(name);
    path.scrollIntoView({ block: 'center', inline: 'nearest' });
    const rect = page.overlay.getBoundingClientRect();
    return {
      x: rect.left + (piece.number[0] / this.model.page.width_mm) * rect.width,
      y: rect.top + (piece.number[1] / this.model.page.height_mm) * rect.height,
    };
  }
}
