// assembly.html: the 3D model and the pattern pages side by side, one selection shared by both,
// and the build order step by step. The page state is window.viewer (read by the browser tests).

import { dataText, readModel } from './model.js';
import { ModelView } from './scene.js';
import { PageView } from './pages.js';

const $ = (id) => document.getElementById(id);

function seamChip(piece, seam, model, onHover) {
  const chip = document.createElement('span');
  chip.className = 'seam';
  const partner = model.byName.get(seam.partner);
  chip.textContent = partner === piece ? `${seam.label} (itself)` : `${seam.label} \u2194 ${seam.partner}`;
  chip.addEventListener('mouseenter', (event) => onHover({ piece, seam }, event));
  chip.addEventListener('mouseleave', () => onHover(null));
  return chip;
}

class Viewer {
  constructor(model) {
    this.model = model;
    this.selected = null;
    this.hovered = null;
    this.step = model.steps.length;
    this.ready = false;
    this.firstRenderMs = null;
    document.title = `${model.name}: assembly`;
    $('title').textContent = `${model.name}: assembly`;
    const count = model.pieces.length;
    $('piece-count').textContent = `${count} ${count === 1 ? 'piece' : 'pieces'} on ${model.pageCount} ${model.pageCount === 1 ? 'page' : 'pages'}` +
      (model.parts > 1 ? `, ${model.parts} separate parts` : '');
    if (model.notes.length) {
      $('notes').textContent = model.notes.join(' ');
      $('notes').hidden = false;
    }
    this.view = new ModelView($('view3d'), model, (name) => this.select(name, { from: '3d' }));
    this.pages = new PageView($('pages'), model, {
      pick: (name) => this.select(name, { from: 'page' }),
      hoverLabel: (hovered, event) => this.hover(hovered, event),
    });
    this.setupSteps();
    this.view.onFirstRender = () => {
      this.firstRenderMs = performance.now();
      this.ready = true;
    };
    this.view.render();
  }

  setupSteps() {
    const slider = $('step');
    slider.min = String(Math.min(1, this.model.steps.length));
    slider.max = String(this.model.steps.length);
    slider.value = String(this.step);
    slider.disabled = this.model.steps.length <= 1;
    slider.addEventListener('input', () => this.setStep(Number(slider.value)));
    $('step-back').addEventListener('click', () => this.setStep(this.step - 1));
    $('step-next').addEventListener('click', () => this.setStep(this.step + 1));
    window.addEventListener('keydown', (event) => {
      const moves = { ArrowLeft: -1, ArrowDown: -1, ArrowRight: 1, ArrowUp: 1 };
      if (event.key in moves) {
        event.preventDefault();  // the slider would move a second time
        this.setStep(this.step + moves[event.key]);
      } else if (event.key === 'Home') {
        this.setStep(1);
      } else if (event.key === 'End') {
        this.setStep(this.model.steps.length);
      } else if (event.key === 'Escape') {
        this.select(null, { from: 'key' });
      }
    });
    this.setStep(this.step);
  }

  setStep(step) {
    const steps = this.model.steps;
    if (!steps.length) return;
    this.step = Math.max(1, Math.min(steps.length, step));
    $('step').value = String(this.step);
    $('step-number').textContent = `${this.step} / ${steps.length}`;
    const current = steps[this.step - 1];
    const glued = new Set(current.labels);
    $('step-text').textContent = `Step ${current.text}`;
    this.view.showStep(this.step, current.labels.map((label) => ({ piece: current.piece, label })));
    this.pages.showStep(this.step, glued);
  }

  select(name, { from }) {
    const piece = name ? this.model.byName.get(name) : null;
    this.selected = piece ? piece.name : null;
    this.view.select(this.selected);
    this.pages.select(this.selected, from === '3d');
    if (piece && from === 'page') this.view.turnTo(piece.name);
    this.showInfo(piece);
  }

  showInfo(piece) {
    const info = $('info');
    info.replaceChildren();
    info.hidden = !piece;
    if (!piece) return;
    const heading = document.createElement('h2');
    heading.textContent = `Piece ${piece.name}`;
    const where = document.createElement('div');
    const step = this.model.steps[piece.step - 1];
    where.textContent = `page ${piece.page} \u00b7 step ${piece.step} of ${this.model.steps.length}: ${step ? step.text.replace(/^\d+: /, '') : ''}`;
    const seams = document.createElement('div');
    for (const seam of piece.seams) seams.append(seamChip(piece, seam, this.model, (h, e) => this.hover(h, e)));
    info.append(heading, where, seams);
  }

  // A seam label under the pointer: its partner on the pages and in 3D, and a tooltip.
  hover(hovered, event) {
    this.hovered = hovered ? { piece: hovered.piece.name, label: hovered.seam.label, partner: hovered.seam.partner } : null;
    const tooltip = $('tooltip');
    this.pages.showPartner(hovered);
    if (!hovered) {
      tooltip.hidden = true;
      this.view.highlightPartner(null);
      this.setStep(this.step);
      return;
    }
    const partner = this.model.byName.get(hovered.seam.partner);
    tooltip.textContent = partner === hovered.piece
      ? `${hovered.seam.label}: glued to itself (piece ${partner.name})`
      : partner ? `${hovered.seam.label}: glued to piece ${partner.name} on page ${partner.page}`
        : `${hovered.seam.label}: no partner`;
    tooltip.hidden = false;
    if (event) {
      tooltip.style.left = `${event.clientX + 14}px`;
      tooltip.style.top = `${event.clientY + 14}px`;
    }
    this.view.highlightPartner(partner ? partner.name : null);
    this.view.drawSeams([{ piece: hovered.piece, label: hovered.seam.label }]);
  }

  // What the page shows, for tests and tools.
  state() {
    return {
      selected: this.selected,
      selected3d: this.view.glowingAsSelected(),
      selectedOnPage: [...document.querySelectorAll('.overlay .piece.selected')].map((p) => p.dataset.piece),
      step: this.step,
      steps: this.model.steps.length,
      visible: this.view.visibleNames(),
      hovered: this.hovered,
    };
  }

  screenPointOf(name) {
    return this.view.screenPointOf(name);
  }

  pagePointOf(name) {
    return this.pages.pointOf(name);
  }
}

async function start() {
  const model = readModel(await dataText($('papercraft-data').textContent));
  window.viewer = new Viewer(model);
}

start().catch((error) => {
  const failure = document.createElement('p');
  failure.id = 'failure';
  failure.textContent = `This page could not show the model: ${error.message}`;
  document.body.prepend(failure);
  console.error(error);
});
