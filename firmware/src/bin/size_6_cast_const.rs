//! Size firmware: the linear shape cast alone (f32), B moving against A, the polygons declared as constants (`Polygon::from_array`).
#![no_std]
#![no_main]

#[path = "../size_common.rs"]
#[macro_use]
mod common;

polygon_firmware!(common::with_const_polygons => cast);
