//! Reading the JavaScript API's arguments: every value is checked before
//! anything is read or changed, and a bad one is refused with a message
//! that names the call, the argument and what was expected
//! ("select(kind, id): id must be a whole number from 0, not 'abc'").

use eframe::wasm_bindgen::{self, JsCast as _, JsValue, prelude::wasm_bindgen};

use edgewise_core::mesh::Structure;

use edgewise_model::algorithm::session::Argument;

// Catching forms of the reflection calls the arguments go through. A page
// can pass a Proxy whose traps throw, or a revoked one; js-sys's own
// bindings let that exception escape the command, which must instead
// return a rejected Promise.
#[wasm_bindgen]
extern "C" {
    #[wasm_bindgen(catch, js_namespace = Array, js_name = isArray)]
    fn is_array_or_throw(value: &JsValue) -> Result<bool, JsValue>;
    #[wasm_bindgen(catch, js_namespace = Object, js_name = keys)]
    fn keys_or_throw(value: &JsValue) -> Result<js_sys::Array, JsValue>;
}

/// Whether `value` is an array; a revoked Proxy is not.
pub(super) fn is_array(value: &JsValue) -> bool {
    is_array_or_throw(value).unwrap_or(false)
}

/// The first `most` items of an array argument and its length, read one by
/// one (an array of length 2³² − 1 is not copied), refused when reading
/// one throws.
pub(super) fn items(
    call: &str,
    argument: &str,
    array: &JsValue,
    most: usize,
) -> Result<(Vec<JsValue>, usize), String> {
    let length = property(call, argument, array, "length")?
        .as_f64()
        .map_or(0, |n| n as usize);
    let items = (0..length.min(most))
        .map(|index| property(call, argument, array, &index.to_string()))
        .collect::<Result<_, _>>()?;
    Ok((items, length))
}

/// `edit(op, ids): ids could not be read: it threw 'TypeError: …'`.
fn unreadable(call: &str, argument: &str, error: &JsValue) -> String {
    let thrown = error
        .dyn_ref::<js_sys::Error>()
        .map(|error| String::from(error.to_string()))
        .or_else(|| error.as_string())
        .unwrap_or_else(|| described(error));
    format!(
        "{call}: {argument} could not be read: it threw '{}'",
        shown(&thrown)
    )
}

/// `object[key]`, refused when the property's getter or the Proxy throws.
fn property(call: &str, argument: &str, object: &JsValue, key: &str) -> Result<JsValue, String> {
    js_sys::Reflect::get(object, &key.into()).map_err(|error| unreadable(call, argument, &error))
}

/// The longest name, file name or option value the API takes.
pub(super) const MAX_NAME_CHARS: usize = 256;

/// "select(kind, id): id must be a whole number from 0, not 'abc'".
pub(super) fn expected(call: &str, argument: &str, what: &str, value: &JsValue) -> String {
    format!(
        "{call}: {argument} must be {what}, not {}",
        described(value)
    )
}

/// A JavaScript value as a message shows it: short, and typed.
pub(super) fn described(value: &JsValue) -> String {
    if value.is_undefined() {
        "undefined (it is missing)".to_owned()
    } else if value.is_null() {
        "null".to_owned()
    } else if let Some(text) = value.as_string() {
        format!("the string '{}'", shown(&text))
    } else if let Some(n) = value.as_f64() {
        format!("{n}")
    } else if let Some(b) = value.as_bool() {
        format!("{b}")
    } else if value.is_bigint() {
        "a BigInt".to_owned()
    } else if value.is_symbol() {
        "a Symbol".to_owned()
    } else if is_array(value) {
        "an array".to_owned()
    } else if value.is_function() {
        "a function".to_owned()
    } else {
        "an object".to_owned()
    }
}

/// User text quoted in a message: at most 40 characters, escaped.
pub(super) fn shown(text: &str) -> String {
    edgewise_core::lang::diagnostic::shorten(text, 40)
        .chars()
        .flat_map(char::escape_debug)
        .collect()
}

/// A whole number from 0 that a JavaScript number holds exactly.
pub(super) fn whole_number(call: &str, argument: &str, value: &JsValue) -> Result<u64, String> {
    const MAX_EXACT: f64 = 9_007_199_254_740_991.0; // Number.MAX_SAFE_INTEGER
    value
        .as_f64()
        .filter(|n| n.fract() == 0.0 && (0.0..=MAX_EXACT).contains(n))
        .map(|n| n as u64)
        .ok_or_else(|| expected(call, argument, "a whole number from 0", value))
}

/// A string argument, refused before it is copied out of JavaScript when it
/// holds more than `limit` UTF-16 units (a lower bound on its UTF-8 bytes).
pub(super) fn text_argument(
    call: &str,
    argument: &str,
    value: &JsValue,
    limit: usize,
) -> Result<String, String> {
    let Some(text) = value.dyn_ref::<js_sys::JsString>() else {
        return Err(expected(call, argument, "a string", value));
    };
    let units = text.length() as usize;
    if units > limit {
        return Err(format!(
            "{call}: {argument} is {units} characters long; it may hold at most {limit}"
        ));
    }
    Ok(String::from(text))
}

/// Refuses an options object that is not an object or has unknown keys, so a
/// misspelled option is named instead of silently ignored.
pub(super) fn check_options(call: &str, options: &JsValue, known: &[&str]) -> Result<(), String> {
    if options.is_undefined() || options.is_null() {
        return Ok(());
    }
    if !options.is_object() || is_array(options) {
        return Err(expected(call, "options", "an object", options));
    }
    let keys = keys_or_throw(options).map_err(|error| unreadable(call, "options", &error))?;
    for key in keys.iter() {
        let key = key.as_string().unwrap_or_default();
        if !known.contains(&key.as_str()) {
            return Err(format!(
                "{call}: there is no option '{}'; the options are {}",
                shown(&key),
                known.join(" and ")
            ));
        }
    }
    Ok(())
}

/// `options[key]` read by `read` (with the argument's name for messages),
/// if the options and the key are present.
fn option<T>(
    call: &str,
    options: &JsValue,
    key: &str,
    read: impl FnOnce(&str, &JsValue) -> Result<T, String>,
) -> Result<Option<T>, String> {
    if options.is_undefined() || options.is_null() {
        return Ok(None);
    }
    let argument = format!("options.{key}");
    let value = property(call, &argument, options, key)?;
    if value.is_undefined() {
        return Ok(None);
    }
    read(&argument, &value).map(Some)
}

/// `options[key]` as a string, if present.
pub(super) fn option_string(
    call: &str,
    options: &JsValue,
    key: &str,
) -> Result<Option<String>, String> {
    option_text(call, options, key, MAX_NAME_CHARS)
}

/// `options[key]` as a string of at most `max_chars`, if present.
pub(super) fn option_text(
    call: &str,
    options: &JsValue,
    key: &str,
    max_chars: usize,
) -> Result<Option<String>, String> {
    option(call, options, key, |argument, value| {
        text_argument(call, argument, value, max_chars)
    })
}

/// `options[key]` as a Boolean, if present.
pub(super) fn option_bool(
    call: &str,
    options: &JsValue,
    key: &str,
) -> Result<Option<bool>, String> {
    option(call, options, key, |argument, value| {
        value
            .as_bool()
            .ok_or_else(|| expected(call, argument, "true or false", value))
    })
}

/// `options[key]` as a whole number, if present.
pub(super) fn option_whole_number(
    call: &str,
    options: &JsValue,
    key: &str,
) -> Result<Option<u64>, String> {
    option(call, options, key, |argument, value| {
        whole_number(call, argument, value)
    })
}

pub(super) fn structure_option(call: &str, options: &JsValue) -> Result<Option<Structure>, String> {
    option_string(call, options, "structure")?
        .map(|name| {
            Structure::parse_link_name(&name).ok_or_else(|| {
                format!(
                    "{call}: options.structure must be 'winged' or 'half', not '{}'",
                    shown(&name)
                )
            })
        })
        .transpose()
}

/// `run`'s arguments object: parameter names to ids, integers or booleans.
pub(super) fn arguments(call: &str, args: &JsValue) -> Result<Vec<(String, Argument)>, String> {
    if args.is_undefined() || args.is_null() {
        return Ok(Vec::new());
    }
    // Not `dyn_ref`: an object made by the page around an iframe belongs to
    // another realm, and fails an `instanceof Object` check.
    if !args.is_object() || is_array(args) {
        return Err(expected(call, "args", "an object such as {v: 0}", args));
    }
    let keys = keys_or_throw(args).map_err(|error| unreadable(call, "args", &error))?;
    let mut out = Vec::new();
    for key in keys.iter() {
        let key = key.as_string().unwrap_or_default();
        let what = format!("args.{}", shown(&key));
        let value = property(call, &what, args, &key)?;
        let argument = if let Some(b) = value.as_bool() {
            Argument::Boolean(b)
        } else if value.as_f64().is_some() {
            Argument::Number(whole_number(call, &what, &value)? as f64)
        } else {
            return Err(expected(
                call,
                &what,
                "a whole number (an id) or a boolean",
                &value,
            ));
        };
        out.push((key, argument));
    }
    Ok(out)
}
