package org.kheperasim.link.tool;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.util.Properties;
import picocli.CommandLine;
import picocli.CommandLine.Model.CommandSpec;

/**
 * The one version both tools print for {@code --version}: the build's project version, written into
 * {@code version.properties} by resource filtering.
 */
public final class ToolVersion implements CommandLine.IVersionProvider {

    @CommandLine.Spec
    CommandSpec spec;

    /** @return the project version, e.g. {@code 0.1.0-SNAPSHOT} */
    public static String version() {
        try (InputStream in = ToolVersion.class.getResourceAsStream("version.properties")) {
            if (in == null) {
                return "unknown (no version.properties: not built by Maven)";
            }
            Properties p = new Properties();
            p.load(in);
            return p.getProperty("version", "unknown");
        } catch (IOException e) {
            throw new UncheckedIOException("cannot read the version: " + e.getMessage(), e);
        }
    }

    @Override
    public String[] getVersion() {
        String tool = spec == null ? "khepera" : spec.root().name();
        return new String[] {tool + " " + version(), "Java " + System.getProperty("java.version") + " ("
                + System.getProperty("java.vm.name") + ")"};
    }
}
