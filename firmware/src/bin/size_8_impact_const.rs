//! Size firmware: the time of impact alone (f32), B moving and turning against A, the polygons declared as constants (`Polygon::from_array`).
#![no_std]
#![no_main]

#[path = "../size_common.rs"]
#[macro_use]
mod common;

polygon_firmware!(common::with_const_polygons => impact);
