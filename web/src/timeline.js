// The shared clock of the page: the time the 3-D view shows and the plots mark, played,
// paused, scrubbed, sped up or slowed down, looped. Listeners hear every change.

import { element } from './data.js';

export class Timeline {
  constructor(t0, t1) {
    this.t0 = t0;
    this.t1 = t1;
    this.time = t0;
    this.playing = false;
    this.speed = 1;
    this.loop = true;
    this.listeners = [];
    this.last = null;
  }

  onChange(listener) { this.listeners.push(listener); }

  set(t, source = null) {
    this.time = Math.min(Math.max(t, this.t0), this.t1);
    for (const listener of this.listeners) listener(this.time, source);
  }

  tick(now) {
    if (this.playing && this.last !== null) {
      let t = this.time + ((now - this.last) / 1000) * this.speed;
      if (t > this.t1) {
        if (this.loop) t = this.t0 + (t - this.t1);
        else { t = this.t1; this.playing = false; }
      }
      this.set(t, 'play');
    }
    this.last = now;
  }

  controls() {
    const play = element('button', { class: 'play', title: 'Play / pause (space)' }, '▶');
    const slider = element('input', { type: 'range', min: 0, max: 1000, value: 0, class: 'scrub',
      'aria-label': 'time' });
    const readout = element('span', { class: 'time-readout' }, '');
    const speed = element('select', { title: 'Playback speed', 'aria-label': 'speed' },
      ...[0.05, 0.1, 0.25, 0.5, 1, 2, 4].map((s) => {
        const option = element('option', { value: s }, `${s}×`);
        if (s === 1) option.selected = true;
        return option;
      }));
    const loop = element('input', { type: 'checkbox', checked: '' });
    const toggle = () => {
      if (!this.playing && this.time >= this.t1) this.set(this.t0);
      this.playing = !this.playing;
      play.textContent = this.playing ? '❚❚' : '▶';
    };
    play.addEventListener('click', toggle);
    document.addEventListener('keydown', (e) => {
      if (e.code === 'Space' && e.target === document.body) { e.preventDefault(); toggle(); }
    });
    slider.addEventListener('input', () => {
      this.set(this.t0 + (this.t1 - this.t0) * (slider.value / 1000), 'slider');
    });
    speed.addEventListener('change', () => { this.speed = Number(speed.value); });
    loop.addEventListener('change', () => { this.loop = loop.checked; });
    this.onChange((t, source) => {
      if (source !== 'slider') {
        slider.value = this.t1 > this.t0 ? Math.round(1000 * (t - this.t0) / (this.t1 - this.t0)) : 0;
      }
      readout.textContent = `t = ${t.toFixed(3)} s`;
      if (!this.playing) play.textContent = '▶';
    });
    readout.textContent = `t = ${this.time.toFixed(3)} s`;
    return element('div', { class: 'timeline' }, play, slider, readout,
      element('label', {}, 'speed ', speed), element('label', {}, loop, ' loop'));
  }
}
