/**
 * Text from a controller (its messages, its exceptions' messages, its class and folder names) made safe
 * to show a person: {@link org.kheperasim.sim.text.Shown} writes the control characters a terminal, a
 * spreadsheet or a bidirectional renderer would act on as visible, reversible escapes.
 */
package org.kheperasim.sim.text;
