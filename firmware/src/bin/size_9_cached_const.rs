//! Size firmware: distance and penetration warm started from a `PairCache` (f32), two steps of one pair, the polygons declared as constants (`Polygon::from_array`).
#![no_std]
#![no_main]

#[path = "../size_common.rs"]
#[macro_use]
mod common;

polygon_firmware!(common::with_const_polygons => cached);
