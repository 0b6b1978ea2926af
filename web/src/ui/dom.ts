// A tiny element builder: h("button", { class: "...", on: { click } }, ["text"]).

type Child = Node | string | number | null | undefined | false;

export interface Props {
  class?: string;
  text?: string;
  title?: string;
  testid?: string;
  attrs?: Record<string, string>;
  style?: Partial<CSSStyleDeclaration>;
  on?: { [K in keyof HTMLElementEventMap]?: (event: HTMLElementEventMap[K]) => void };
}

export function h<K extends keyof HTMLElementTagNameMap>(
  tag: K,
  props: Props = {},
  children: Child[] = [],
): HTMLElementTagNameMap[K] {
  const element = document.createElement(tag);
  if (props.class) element.className = props.class;
  if (props.text !== undefined) element.textContent = props.text;
  if (props.title) element.title = props.title;
  if (props.testid) element.dataset.testid = props.testid;
  if (props.attrs) for (const [k, v] of Object.entries(props.attrs)) element.setAttribute(k, v);
  if (props.style) Object.assign(element.style, props.style);
  if (props.on) {
    for (const [event, handler] of Object.entries(props.on)) {
      element.addEventListener(event, handler as EventListener);
    }
  }
  for (const child of children) {
    if (child === null || child === undefined || child === false) continue;
    element.append(child instanceof Node ? child : String(child));
  }
  return element;
}

export function clear(element: Element): void {
  while (element.firstChild) element.removeChild(element.firstChild);
}

export function byId<T extends HTMLElement = HTMLElement>(id: string): T {
  const element = document.getElementById(id);
  if (element === null) throw new Error(`viewer: #${id} missing from index.html`);
  return element as T;
}

export const BUTTON =
  "inline-flex items-center gap-1.5 rounded-md px-3 py-1.5 text-sm font-medium transition " +
  "disabled:cursor-not-allowed disabled:opacity-40";
export const BUTTON_PRIMARY = `${BUTTON} bg-sky-600 text-white hover:bg-sky-500`;
export const BUTTON_SECONDARY = `${BUTTON} bg-slate-800 text-slate-100 hover:bg-slate-700 ring-1 ring-slate-700`;
export const BUTTON_SMALL =
  "rounded px-2 py-0.5 text-xs font-medium bg-slate-800 text-slate-200 ring-1 ring-slate-700 " +
  "hover:bg-slate-700 disabled:opacity-40 disabled:cursor-not-allowed";
export const INPUT =
  "w-full rounded-md bg-slate-900 px-2 py-1 text-sm text-slate-100 ring-1 ring-slate-700 " +
  "focus:outline-none focus:ring-sky-500";
