# Reads `llvm-objdump -d -C -l` output; prints, for every call or branch to a
# panic entry point, the calling function, the source line and the target.
/^[0-9a-f]+ <.*>:$/ { fn = $0; sub(/^[0-9a-f]+ </, "", fn); sub(/>:$/, "", fn); next }
/^; \// { src = $0; sub(/^; /, "", src); next }
/<(core::panicking::|core::slice::index::|core::option::unwrap_failed|core::result::unwrap_failed|core::option::expect_failed|rust_begin_unwind|__rustc::rust_begin_unwind|core::str::slice_error_fail|core::fmt::)/ && /\t(bl|b|b\.w|blx|beq|bne|beq\.w|bne\.w|bhs|blo|bhi|bls|bge|blt|bgt|ble|bcs|bcc|bmi|bpl)\t/ {
  target = $0; sub(/.*</, "", target); sub(/>.*/, "", target)
  if (fn ~ /^core::|^__rustc::|^rust_begin_unwind/) next
  key = fn " | " src " | " target
  if (!(key in seen)) { seen[key] = 1; print fn "\n    at " src "\n    -> " target }
}
