// The report front-end's data helpers (web/src/data.js), in Node.js without a browser: the arrays
// the report embeds as "f64:"/"f32:" + base64 decoded back to the numbers that were encoded.
//
//   node --test tests/web/data_test.mjs        (CTest: web.data)

import assert from 'node:assert/strict';
import { test } from 'node:test';
import { decode } from '../../web/src/data.js';

const encoded = (kind, array) => `${kind}:${Buffer.from(array.buffer).toString('base64')}`;

// Every length up to 40 values: the byte counts 8n and 4n cover all three paddings (none, one
// '=', two) of base64's last group.
test('decode gives back every value encoded, bit for bit, at every padding', () => {
  const random = (n) => Array.from({ length: n }, (_, i) => Math.sin(1 + 7 * i) * 10 ** ((i % 11) - 5));
  for (let n = 0; n <= 40; n++) {
    const f64 = Float64Array.from(random(n));
    const back64 = decode(encoded('f64', f64));
    assert.ok(back64 instanceof Float64Array);
    assert.deepEqual(Array.from(back64), Array.from(f64), `f64, ${n} values`);
    const f32 = Float32Array.from(random(n));
    const back32 = decode(encoded('f32', f32));
    assert.ok(back32 instanceof Float32Array);
    assert.deepEqual(Array.from(back32), Array.from(f32), `f32, ${n} values`);
  }
  const special = Float64Array.from([0, -0, Infinity, -Infinity, Number.MIN_VALUE, Number.MAX_VALUE]);
  assert.deepEqual(Array.from(decode(encoded('f64', special))), Array.from(special));
  assert.ok(Object.is(decode(encoded('f64', special))[1], -0));
});

test('decode passes through what is not encoded and refuses what is not base64', () => {
  const plain = [1, 2, 3];
  assert.equal(decode(plain), plain);
  assert.throws(() => decode('f64:AAA*AAAA'), /base64: '\*' at 3 is not a digit/);
  assert.throws(() => decode('f64:AAAAAAAAAAA'), /not a multiple of 4/);
  assert.throws(() => decode('f64:AAAAAAAAAAé='), /'é' at 10 is not a digit/);
  assert.throws(() => decode('i32:AAAAAA=='), /unknown array encoding i32:/);
});
