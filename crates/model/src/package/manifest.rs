//! `imsmanifest.xml`: what an LMS reads first. One organization with one
//! item, launched by one SCO (`launch.html`) that lists every file.

use super::{Package, Scorm};
use crate::course_link::escape_attribute as escape;

/// The package's manifest, listing `files` (every file but the manifest).
pub(super) fn manifest(package: &Package, identifier: &str, files: &[String]) -> String {
    let title = escape(&package.title);
    let mut xml = String::from("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n");
    let (namespaces, scorm_type, mastery) = match package.scorm {
        Scorm::V1_2 => (
            concat!(
                " xmlns=\"http://www.imsproject.org/xsd/imscp_rootv1p1p2\"",
                " xmlns:adlcp=\"http://www.adlnet.org/xsd/adlcp_rootv1p2\""
            ),
            "adlcp:scormtype",
            // The LMS judges passed or failed by this too, as the runtime does.
            format!(
                "\n        <adlcp:masteryscore>{}</adlcp:masteryscore>",
                package.pass_mark
            ),
        ),
        Scorm::V2004 => (
            concat!(
                " xmlns=\"http://www.imsglobal.org/xsd/imscp_v1p1\"",
                " xmlns:adlcp=\"http://www.adlnet.org/xsd/adlcp_v1p3\"",
                " xmlns:imsss=\"http://www.imsglobal.org/xsd/imsss\""
            ),
            "adlcp:scormType",
            // cmi.scaled_passing_score: the pass mark, as the LMS gives it.
            format!(
                concat!(
                    "\n        <imsss:sequencing>",
                    "\n          <imsss:objectives>",
                    "\n            <imsss:primaryObjective objectiveID=\"total\" satisfiedByMeasure=\"true\">",
                    "\n              <imsss:minNormalizedMeasure>{}</imsss:minNormalizedMeasure>",
                    "\n            </imsss:primaryObjective>",
                    "\n          </imsss:objectives>",
                    "\n        </imsss:sequencing>"
                ),
                f64::from(package.pass_mark) / 100.0
            ),
        ),
    };
    xml.push_str(&format!(
        "<manifest identifier=\"{identifier}\" version=\"1\"{namespaces}>\n"
    ));
    xml.push_str(&format!(
        concat!(
            "  <metadata>\n",
            "    <schema>ADL SCORM</schema>\n",
            "    <schemaversion>{}</schemaversion>\n",
            "  </metadata>\n",
            "  <organizations default=\"edgewise-organization\">\n",
            "    <organization identifier=\"edgewise-organization\">\n",
            "      <title>{title}</title>\n",
            "      <item identifier=\"edgewise-item\" identifierref=\"edgewise-sco\">\n",
            "        <title>{title}</title>{mastery}\n",
            "      </item>\n",
            "    </organization>\n",
            "  </organizations>\n",
            "  <resources>\n",
            "    <resource identifier=\"edgewise-sco\" type=\"webcontent\" {scorm_type}=\"sco\" href=\"launch.html\">\n",
        ),
        package.scorm.schema_version(),
        title = title,
        mastery = mastery,
        scorm_type = scorm_type,
    ));
    for file in files {
        xml.push_str(&format!("      <file href=\"{}\"/>\n", escape(file)));
    }
    xml.push_str("    </resource>\n  </resources>\n</manifest>\n");
    xml
}
