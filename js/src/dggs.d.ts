// Types of dggs.js: the dggs C core as WebAssembly. Ids are strings ("C401") or BigInts (64-bit integer ids);
// a verb answers in the kind of id it was given. Coordinates are WGS84 degrees, latitude first.

/** A cell id: its string form or its 64-bit integer form. */
export type Cell = string | bigint;
/** Snyder's icosahedral equal-area projection (the default) or the vertex-oriented great circle projection. */
export type Projection = "ISEA" | "IVEA";
export type FillMode = "center" | "contains" | "overlaps" | "overlapping_bbox";
export type AreaUnit = "m^2" | "km^2" | "rads^2";
export type LatLng = [lat: number, lng: number];

export interface ProjectionOptions {
  /** Default "ISEA". */
  projection?: Projection;
}
export interface BoundaryOptions extends ProjectionOptions {
  /** Points added along each edge (0..100000; default 0: the three corners). */
  densify?: number;
}
export interface LimitOptions {
  /** Most cells to build (default MAX_CELLS); more throws a DggsError. */
  maxCells?: number;
}
export interface PolygonOptions extends ProjectionOptions, LimitOptions {
  /** Default "center": the cells whose centre is inside. */
  mode?: FillMode;
  /** Points are [lng, lat] (GeoJSON order) instead of [lat, lng]. */
  geoJson?: boolean;
  /** Answer a BigUint64Array instead of string ids. */
  asBigInt?: boolean;
}

export const MAX_LEVEL: 28;
export const MAX_CELLS: number;

/** An error of the C core (`code` its dggs_error, `errorName` such as "E_CELL") or of an argument. */
export class DggsError extends Error {
  code: number;
  errorName: string;
}

/** The module's functions, as init resolves them. */
export type Dggs = typeof import("./dggs.js");

/**
 * Load the WebAssembly module (dist/dggs.wasm beside the package by default: from disk under node, by fetch in a
 * browser), or from a URL, path, bytes, Response or compiled module. Call it once before any other function.
 */
export function init(source?: string | URL | BufferSource | Response | WebAssembly.Module): Promise<Dggs>;

export function stringToCell(id: string): bigint;
export function cellToString(cell: bigint): string;
/** Whether the value is a cell id; never throws. */
export function isValidCell(cell: unknown): boolean;
export function getLevel(cell: Cell): number;
export function getFace(cell: Cell): number;
/** A cell's area, or every cell's at a level: the WGS84 ellipsoid's area over the level's cell count. */
export function cellArea(cellOrLevel: Cell | number, unit?: AreaUnit): number;
export function getNumCells(level: number): number;

export function latLngToCell(lat: number, lng: number, level: number, opts?: ProjectionOptions & { asBigInt?: false }): string;
export function latLngToCell(lat: number, lng: number, level: number, opts: ProjectionOptions & { asBigInt: true }): bigint;
/** The centre of a cell. */
export function cellToLatLng(cell: Cell, opts?: ProjectionOptions): LatLng;
/** Corners counter-clockwise seen from outside, each followed by `densify` edge points; not closed. */
export function cellToBoundary(cell: Cell, opts?: BoundaryOptions): LatLng[];

/** Batch point location: one id per point. */
export function latLngToCells(
  lat: Float64Array | ArrayLike<number>,
  lng: Float64Array | ArrayLike<number>,
  level: number,
  opts?: ProjectionOptions,
): BigUint64Array;
/** Centres as n (lat, lng) pairs. */
export function cellsToLatLngs(cells: BigUint64Array | ArrayLike<Cell>, opts?: ProjectionOptions): Float64Array;
/** Boundaries: cell i's 3 (densify + 1) (lat, lng) pairs from 6 (densify + 1) i. */
export function cellsToBoundaries(cells: BigUint64Array | ArrayLike<Cell>, opts?: BoundaryOptions): Float64Array;

/** The ancestor at `level` (default one level up). */
export function cellToParent<C extends Cell>(cell: C, level?: number): C extends string ? string : bigint;
/** The descendant at `level` (default one level down) holding the cell's centre. */
export function cellToCenterChild<C extends Cell>(cell: C, level?: number): C extends string ? string : bigint;
/** The descendants at `level` (default one level down), in id order. */
export function cellToChildren<C extends Cell>(cell: C, level?: number, opts?: LimitOptions): (C extends string ? string : bigint)[];

/** The fewest cells covering the area of `cells`, sorted. */
export function compactCells(cells: BigUint64Array): BigUint64Array;
export function compactCells<C extends Cell>(cells: ArrayLike<C>): C[];
/** Every descendant at `level` of the area `cells` cover, sorted and unique. */
export function uncompactCells(cells: BigUint64Array, level: number, opts?: LimitOptions): BigUint64Array;
export function uncompactCells<C extends Cell>(cells: ArrayLike<C>, level: number, opts?: LimitOptions): C[];

/** The cells within k edge steps (the cell included), sorted by id. */
export function gridDisk<C extends Cell>(cell: C, k?: number, opts?: LimitOptions): (C extends string ? string : bigint)[];
/** The cells exactly k edge steps away, sorted by id. */
export function gridRing<C extends Cell>(cell: C, k?: number, opts?: LimitOptions): (C extends string ? string : bigint)[];
/** The three cells across the cell's edges. */
export function edgeNeighbors<C extends Cell>(cell: C): (C extends string ? string : bigint)[];
/** Edge steps on a shortest path between two cells of one level. */
export function gridDistance(a: Cell, b: Cell): number;

/**
 * The cells of `level` of a polygon given as rings (shell, then holes; several shells allowed) of [lat, lng]
 * points ([lng, lat] with geoJson), longitudes in -180..180; sorted.
 */
export function polygonToCells(polygon: ArrayLike<ArrayLike<number>>[], level: number, opts?: PolygonOptions & { asBigInt?: false }): string[];
export function polygonToCells(polygon: ArrayLike<ArrayLike<number>>[], level: number, opts: PolygonOptions & { asBigInt: true }): BigUint64Array;
