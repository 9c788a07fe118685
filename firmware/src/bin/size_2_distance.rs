//! Size firmware: polygon intersection + distance (f32), with the polygons built at run time (`Polygon::new`).
#![no_std]
#![no_main]

#[path = "../size_common.rs"]
#[macro_use]
mod common;

polygon_firmware!(common::with_polygons::<f32> => intersects, distance);
