/**
 * A conversation with one robot over a {@link org.kheperasim.link.io.Link}: the boot banner thrown
 * away, the {@code B} handshake, one command outstanding at a time with a timeout, retries and
 * resynchronisation on the reply letter, and errors that name the command.
 */
package org.kheperasim.link.session;
