//! Size firmware: the contact manifold alone (f32), the polygons declared as constants (`Polygon::from_array`).
#![no_std]
#![no_main]

#[path = "../size_common.rs"]
#[macro_use]
mod common;

polygon_firmware!(common::with_const_polygons => manifold);
