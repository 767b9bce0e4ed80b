# Shared by the setup scripts (sourced, not run): messages, failing with the script's name, and running a
# command as root (directly when we are root, else through sudo).

say() { printf '==> %s\n' "$*"; }
fail() {
    printf '%s: %s\n' "${0##*/}" "$*" >&2
    exit 1
}

as_root() {
    if [[ $(id -u) -eq 0 ]]; then
        "$@"
    elif command -v sudo >/dev/null; then
        sudo "$@"
    else
        fail "need root rights to install packages, but this is not root and sudo is missing"
    fi
}
