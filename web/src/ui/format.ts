// Number formatting for panels and tables.

export function percent(value: number | null | undefined, digits = 1): string {
  if (value === null || value === undefined || !Number.isFinite(value)) return "—";
  return `${(value * 100).toFixed(digits)}%`;
}

export function fixed(value: number | null | undefined, digits = 3): string {
  if (value === null || value === undefined || !Number.isFinite(value)) return "—";
  return value.toFixed(digits);
}

export function integer(value: number | null | undefined): string {
  if (value === null || value === undefined || !Number.isFinite(value)) return "—";
  return Math.round(value).toLocaleString("en-US");
}

export function bytes(n: number): string {
  if (n < 1024) return `${n} B`;
  if (n < 1024 * 1024) return `${(n / 1024).toFixed(1)} KB`;
  return `${(n / 1024 / 1024).toFixed(1)} MB`;
}

export function point(p: readonly number[] | undefined): string {
  if (!p) return "—";
  return `(${p.map((x) => x.toFixed(2)).join(", ")})`;
}

export function ms(value: number): string {
  return value < 1000 ? `${Math.round(value)} ms` : `${(value / 1000).toFixed(2)} s`;
}

/** Decimals that show `x` with `digits` significant digits (for sliders: 0.200 not 0.200235559148495). */
export function significantDecimals(x: number, digits = 3): number {
  if (!Number.isFinite(x) || x === 0) return digits;
  return Math.max(0, Math.min(10, digits - 1 - Math.floor(Math.log10(Math.abs(x)))));
}
