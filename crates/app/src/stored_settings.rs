//! The settings kept where the platform keeps them: the browser's local
//! storage (natively, they last the session).

use edgewise_model::settings::Settings;

/// The local-storage key.
pub const STORAGE_KEY: &str = "edgewise.settings";

/// Loads the settings saved in this browser, if any (natively, settings
/// last the session).
pub fn load_stored() -> (Settings, Option<String>) {
    match crate::platform::load_settings(STORAGE_KEY) {
        Some(json) => Settings::from_json(&json),
        None => (Settings::default(), None),
    }
}

/// Saves the settings where the platform keeps them.
pub fn store(settings: &Settings) {
    crate::platform::store_settings(STORAGE_KEY, &settings.to_json());
}
