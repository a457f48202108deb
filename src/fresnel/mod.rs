//! Fresnel reflectance: placeholder.
