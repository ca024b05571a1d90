/** The {@code khepera-link} command line: ports, run, console, check and bench. */
package org.kheperasim.link.cli;
